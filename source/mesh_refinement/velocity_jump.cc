// The velocity jump indicator: how much the velocity varies over a cell,
// scaled to maximum 1 over all ranks. A wave front carries a jump of the
// velocity, which is as large on a coarse cell as on a fine one, while
// gradient indicators (Kelly, recovery) grow with the gradient and so rank
// the fine cells of the oscillations behind a front above the coarse cells
// the front is about to enter.

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/vector.h>

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/interface.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dyncontact
{
  namespace MeshRefinement
  {
    /// On each cell, the Euclidean norm over the components of the largest
    /// difference between two of the cell's nodal values of @p field;
    /// below 1e-9 of the largest nodal value zero (a uniform field marks no
    /// cell).
    template <int dim>
    void
    jump_indicators(const SimulatorAccess<dim> &access,
                    const VectorType           &field,
                    Vector<float>              &eta)
    {
      const SemiDiscreteSystem<dim> &system  = access.get_system();
      const auto                    &ghosted = system.ghosted(field);
      const FiniteElement<dim>      &fe      = system.get_fe();
      Vector<double>                 values(fe.n_dofs_per_cell());
      const double                   floor =
        1e-9 *
        Utilities::MPI::max(field.linfty_norm(), access.get_mpi_communicator());
      for (const auto &cell : system.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_values(ghosted, values);
            std::array<double, dim> low, high;
            low.fill(std::numeric_limits<double>::max());
            high.fill(-std::numeric_limits<double>::max());
            for (unsigned int i = 0; i < values.size(); ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                low[c]               = std::min(low[c], values[i]);
                high[c]              = std::max(high[c], values[i]);
              }
            double jump = 0.;
            for (unsigned int c = 0; c < dim; ++c)
              jump += (high[c] - low[c]) * (high[c] - low[c]);
            jump                           = std::sqrt(jump);
            eta[cell->active_cell_index()] = jump > floor ? jump : 0.;
          }
    }

    template <int dim>
    class VelocityJump : public FieldCriterion<dim, jump_indicators<dim>, true>
    {};

    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(
      VelocityJump,
      "velocity jump",
      "the largest difference of the velocity between the nodes of a "
      "cell: the jump a wave front carries, as large on a coarse cell as "
      "on a fine one, so that the front is refined before the "
      "oscillations behind it (with Front widening, for wave fronts)")
  } // namespace MeshRefinement
} // namespace dyncontact
