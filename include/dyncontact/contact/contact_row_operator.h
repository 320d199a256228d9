#ifndef dyncontact_contact_contact_row_operator_h
#define dyncontact_contact_contact_row_operator_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dyncontact/contact/contact_rows.h>

#include <memory>
#include <vector>

class Epetra_Import;

namespace dyncontact
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;

  /**
   * The contact rows as an operator on distributed vectors: (C v)_p and
   * (C v - g)_p for the rows of this rank (those of its locally owned slave
   * nodes), from a vector with the ghost entries the rows need (the master
   * DoFs at their image points). No reduction: a rank that needs a global
   * figure reduces it itself.
   */
  class ContactRowOperator
  {
  public:
    explicit ContactRowOperator(const MPI_Comm comm);

    /// Sets the partitioning and the rows (once per mesh).
    void
    reinit(const IndexSet    &locally_owned,
           const IndexSet    &locally_relevant,
           const ContactRows &rows);

    /// @p v with the ghost entries of the rows' DoFs (valid until the next
    /// call): what reading a row's entries needs.
    const VectorType &
    with_row_ghosts(const VectorType &v) const;

    /// (C v)_p for this rank's rows (no gap subtracted).
    std::vector<double>
    apply(const VectorType &v) const;

    /// (C v - g)_p for this rank's rows.
    std::vector<double>
    constraint_values(const VectorType &v) const;

    /// The locally relevant DoFs plus every DoF a row touches.
    const IndexSet &
    ghost_set() const
    {
      return ghosts;
    }

    const ContactRows &
    rows() const
    {
      return *contact_rows;
    }

    std::size_t
    size() const
    {
      return contact_rows == nullptr ? 0 : contact_rows->size();
    }

  private:
    MPI_Comm           comm;
    IndexSet           locally_owned;
    IndexSet           ghosts;
    const ContactRows *contact_rows = nullptr;
    /// v with the ghost entries of the rows' DoFs (with_row_ghosts())
    mutable VectorType ghosted_row_dofs;
    /// the import into it from the map of the last v (kept: deal.II's
    /// assignment builds one at every copy); it holds that map
    mutable std::shared_ptr<Epetra_Import> row_import;
  };
} // namespace dyncontact

#endif
