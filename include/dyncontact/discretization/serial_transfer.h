#ifndef dyncontact_discretization_serial_transfer_h
#define dyncontact_discretization_serial_transfer_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace dyncontact
{
  using namespace dealii;

  /**
   * The transfer of vectors through a refinement of deal.II's serial
   * triangulation on one rank, as deal.II 9.4's serial SolutionTransfer
   * does it and to the same bits (the same values read, restricted and
   * prolongated with the element's matrices, written in the same order of
   * cells), without its std::map of cells and its writes entry by entry
   * into the Trilinos vectors: the values are kept per cell in one array
   * indexed by (level, index), read from and written to the vectors' local
   * arrays (on one rank the vectors' local index is the DoF index).
   */
  template <int dim>
  class SerialTransfer
  {
  public:
    /// Before Triangulation::execute_coarsening_and_refinement(): keeps
    /// the values of @p in on each cell that stays or is refined, and on
    /// each parent whose children are coarsened the values restricted to
    /// it.
    void
    prepare(const DoFHandler<dim>                                    &dofs,
            const std::vector<const TrilinosWrappers::MPI::Vector *> &in);

    /// After the DoFs are distributed on the new mesh: writes the kept
    /// values into @p out (of the new DoFs), prolongated to the children of
    /// refined cells.
    void
    interpolate(const DoFHandler<dim>                              &dofs,
                const std::vector<TrilinosWrappers::MPI::Vector *> &out) const;

  private:
    static constexpr unsigned int none = static_cast<unsigned int>(-1);
    /// per level and cell index, the cell's slot in @p values (or none)
    std::vector<std::vector<unsigned int>> slots;
    /// per slot and vector the values of the element's DoFs
    std::vector<double> values;
    unsigned int        n_vectors = 0;
  };
} // namespace dyncontact

#endif
