#include <deal.II/base/utilities.h>

#include <dyncontact/contact/contact_row_operator.h>

#include <Epetra_Import.h>

namespace dyncontact
{
  ContactRowOperator::ContactRowOperator(const MPI_Comm comm)
    : comm(comm)
  {}



  void
  ContactRowOperator::reinit(const IndexSet    &owned,
                             const IndexSet    &relevant,
                             const ContactRows &rows)
  {
    locally_owned = owned;
    ghosts        = relevant;
    std::vector<types::global_dof_index> touched;
    // the rows' DoFs and the component-0 DoFs of the master nodes at their
    // images (the contact-zone criterion marks these; a zero coefficient,
    // e.g. of a vertical normal, leaves them out of the entries)
    for (const ContactRow &row : rows.rows)
      {
        for (const auto &entry : row.entries)
          touched.push_back(entry.first);
        for (const auto &node : row.master_nodes)
          touched.push_back(node.first);
      }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    ghosts.add_indices(touched.begin(), touched.end());
    ghosts.compress();
    // apply() reads only the rows' own DoFs: a ghosted vector with just
    // those, made once per mesh
    IndexSet row_dofs(owned.size());
    row_dofs.add_indices(touched.begin(), touched.end());
    row_dofs.compress();
    ghosted_row_dofs.reinit(owned, row_dofs, comm);
    row_import.reset();
    contact_rows = &rows;
  }



  const VectorType &
  ContactRowOperator::with_row_ghosts(const VectorType &v) const
  {
    // what deal.II's assignment does between different maps (an import
    // with Insert), with the import kept for the next v of the same map
    // (the import holds its source map, whose data cannot be freed and
    // reused by another map while it is kept)
    const Epetra_BlockMap &source = v.trilinos_vector().Map();
    if (row_import == nullptr ||
        row_import->SourceMap().DataPtr() != source.DataPtr())
      row_import = std::make_shared<Epetra_Import>(
        ghosted_row_dofs.trilinos_vector().Map(), source);
    const int error =
      ghosted_row_dofs.trilinos_vector().Import(v.trilinos_vector(),
                                                *row_import,
                                                Insert);
    AssertThrow(error == 0, ExcMessage("Epetra_Import failed."));
    return ghosted_row_dofs;
  }



  std::vector<double>
  ContactRowOperator::apply(const VectorType &v) const
  {
    const VectorType   &ghosted = with_row_ghosts(v);
    std::vector<double> values(size(), 0.);
    for (unsigned int p = 0; p < values.size(); ++p)
      for (const auto &entry : contact_rows->rows[p].entries)
        values[p] += entry.second * ghosted(entry.first);
    return values;
  }



  std::vector<double>
  ContactRowOperator::constraint_values(const VectorType &v) const
  {
    std::vector<double> values = apply(v);
    for (unsigned int p = 0; p < values.size(); ++p)
      values[p] -= contact_rows->rows[p].gap;
    return values;
  }
} // namespace dyncontact
