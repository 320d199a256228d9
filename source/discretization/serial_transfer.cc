#include <deal.II/base/geometry_info.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <dyncontact/discretization/serial_transfer.h>

#include <algorithm>

namespace dyncontact
{
  namespace
  {
    /// A Trilinos vector on one rank as the array of its DoFs.
    template <typename TrilinosVector>
    auto
    dof_values(TrilinosVector &vector)
    {
      AssertThrow(vector.locally_owned_size() == vector.size(),
                  ExcMessage("the serial transfer needs all DoFs on one rank"));
      return make_array_view(vector.begin(), vector.end());
    }



    /// The nonzero entries of one of an element's prolongation matrices,
    /// row by row. Its product sums the products of FullMatrix::vmult()
    /// in the same order, without those of the zero entries: for finite
    /// values these are +0 or -0, and adding them changes no sum that
    /// starts at +0 (such a sum is never -0), so that the result has the
    /// same bits at a fraction of the cost (a Q2 element in 3D has 81
    /// columns, about 5 nonzeros per row).
    class SparseProlongation
    {
    public:
      explicit SparseProlongation(const FullMatrix<double> &matrix)
      {
        row_start.push_back(0);
        for (unsigned int i = 0; i < matrix.m(); ++i)
          {
            for (unsigned int j = 0; j < matrix.n(); ++j)
              if (matrix(i, j) != 0.)
                {
                  column.push_back(j);
                  entry.push_back(matrix(i, j));
                }
            row_start.push_back(column.size());
          }
      }

      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        for (unsigned int i = 0; i + 1 < row_start.size(); ++i)
          {
            double sum = 0.;
            for (unsigned int k = row_start[i]; k < row_start[i + 1]; ++k)
              sum += src[column[k]] * entry[k];
            dst[i] = sum;
          }
      }

    private:
      std::vector<unsigned int> row_start, column;
      std::vector<double>       entry;
    };



    /// The sparse prolongation matrices of an element, made for each
    /// refinement case at its first use.
    template <int dim>
    class Prolongations
    {
    public:
      explicit Prolongations(const FiniteElement<dim> &fe)
        : fe(fe)
        , by_case(RefinementCase<dim>::isotropic_refinement + 1)
      {}

      const SparseProlongation &
      get(const unsigned int child, const RefinementCase<dim> &refinement)
      {
        auto &matrices = by_case[refinement];
        if (matrices.empty())
          for (unsigned int c = 0;
               c < GeometryInfo<dim>::n_children(refinement);
               ++c)
            matrices.emplace_back(fe.get_prolongation_matrix(c, refinement));
        return matrices[child];
      }

    private:
      const FiniteElement<dim>                    &fe;
      std::vector<std::vector<SparseProlongation>> by_case;
    };



    /// An active cell's DoF values; a refined cell's prolongated to its
    /// children, as DoFCellAccessor::set_dof_values_by_interpolation().
    template <int dim>
    void
    set_by_interpolation(const typename DoFHandler<dim>::cell_iterator &cell,
                         const Vector<double>                          &local,
                         Prolongations<dim>                   &prolongations,
                         std::vector<types::global_dof_index> &dof_indices,
                         const ArrayView<double>              &out)
    {
      if (cell->is_active())
        {
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < dof_indices.size(); ++i)
            out[dof_indices[i]] = local[i];
          return;
        }
      Vector<double> child_values(local.size());
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        {
          prolongations.get(c, cell->refinement_case())
            .vmult(child_values, local);
          set_by_interpolation<dim>(
            cell->child(c), child_values, prolongations, dof_indices, out);
        }
    }
  } // namespace



  template <int dim>
  void
  SerialTransfer<dim>::prepare(
    const DoFHandler<dim>                                    &dofs,
    const std::vector<const TrilinosWrappers::MPI::Vector *> &in)
  {
    const auto        &tria = dofs.get_triangulation();
    const unsigned int n    = dofs.get_fe().n_dofs_per_cell();
    n_vectors               = in.size();
    slots.resize(tria.n_levels());
    for (unsigned int level = 0; level < tria.n_levels(); ++level)
      slots[level].assign(tria.n_raw_cells(level), none);

    // the cells deal.II's SolutionTransfer keeps: active ones that stay or
    // are refined, and the parents of coarsened ones
    unsigned int n_slots = 0;
    for (const auto &cell : dofs.cell_iterators())
      if (cell->is_active() ? !cell->coarsen_flag_set() :
                              cell->child(0)->coarsen_flag_set())
        slots[cell->level()][cell->index()] = n_slots++;
    values.resize(std::size_t(n_slots) * n_vectors * n);

    // the vectors as deal.II vectors for the restriction to the parents
    std::vector<Vector<double>> copies;
    for (const auto *vector : in)
      {
        const auto array = dof_values(*vector);
        copies.emplace_back(array.begin(), array.end());
      }
    Vector<double>                       local(n);
    std::vector<types::global_dof_index> dof_indices(n);
    for (const auto &cell : dofs.cell_iterators())
      {
        const unsigned int slot = slots[cell->level()][cell->index()];
        if (slot == none)
          continue;
        if (cell->is_active())
          cell->get_dof_indices(dof_indices);
        for (unsigned int j = 0; j < n_vectors; ++j)
          {
            double *kept =
              values.data() + (std::size_t(slot) * n_vectors + j) * n;
            if (cell->is_active())
              for (unsigned int i = 0; i < n; ++i)
                kept[i] = copies[j][dof_indices[i]];
            else
              {
                cell->get_interpolated_dof_values(copies[j], local);
                std::copy(local.begin(), local.end(), kept);
              }
          }
      }
  }



  template <int dim>
  void
  SerialTransfer<dim>::interpolate(
    const DoFHandler<dim>                              &dofs,
    const std::vector<TrilinosWrappers::MPI::Vector *> &out) const
  {
    AssertDimension(out.size(), n_vectors);
    const unsigned int             n = dofs.get_fe().n_dofs_per_cell();
    std::vector<ArrayView<double>> arrays;
    for (auto *vector : out)
      arrays.push_back(dof_values(*vector));
    Vector<double>                       local(n);
    std::vector<types::global_dof_index> dof_indices(n);
    Prolongations<dim>                   prolongations(dofs.get_fe());
    // cell by cell in deal.II's order, so that a DoF shared by cells gets
    // the value of the same cell as with deal.II's SolutionTransfer
    for (const auto &cell : dofs.cell_iterators())
      {
        const unsigned int level = cell->level();
        if (level >= slots.size() ||
            static_cast<unsigned int>(cell->index()) >= slots[level].size())
          continue;
        const unsigned int slot = slots[level][cell->index()];
        if (slot == none)
          continue;
        for (unsigned int j = 0; j < n_vectors; ++j)
          {
            const double *kept =
              values.data() + (std::size_t(slot) * n_vectors + j) * n;
            std::copy(kept, kept + n, local.begin());
            set_by_interpolation<dim>(
              cell, local, prolongations, dof_indices, arrays[j]);
          }
      }
  }

  template class SerialTransfer<2>;
  template class SerialTransfer<3>;
} // namespace dyncontact
