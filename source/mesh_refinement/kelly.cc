// Kelly's error indicators of the displacement or of the velocity, scaled
// to maximum 1 over all ranks.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/error_estimator.h>

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/interface.h>

namespace dyncontact
{
  namespace MeshRefinement
  {
    /// Kelly's indicators of @p field.
    template <int dim>
    void
    kelly_indicators(const SimulatorAccess<dim> &access,
                     const VectorType           &field,
                     Vector<float>              &eta)
    {
      const SemiDiscreteSystem<dim> &system = access.get_system();
      KellyErrorEstimator<dim>::estimate(access.get_mapping(),
                                         system.get_dof_handler(),
                                         QGauss<dim - 1>(
                                           system.get_fe().degree + 1),
                                         {},
                                         system.ghosted(field),
                                         eta);
    }

    template <int dim>
    class KellyDisplacement
      : public FieldCriterion<dim, kelly_indicators<dim>, false>
    {};

    template <int dim>
    class KellyVelocity
      : public FieldCriterion<dim, kelly_indicators<dim>, true>
    {};

    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(KellyDisplacement,
                                             "kelly displacement",
                                             "Kelly's indicator of the "
                                             "displacement")
    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(KellyVelocity,
                                             "kelly velocity",
                                             "Kelly's indicator of the "
                                             "velocity")
  } // namespace MeshRefinement
} // namespace dyncontact
