// Zienkiewicz and Zhu's gradient-recovery indicators of the displacement or
// of the velocity, scaled to maximum 1 over all ranks.

#include <deal.II/lac/vector.h>

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/interface.h>

namespace dyncontact
{
  namespace MeshRefinement
  {
    /// Zienkiewicz and Zhu's indicators of @p field.
    template <int dim>
    void
    recovery_indicators(const SimulatorAccess<dim> &access,
                        const VectorType           &field,
                        Vector<float>              &eta)
    {
      access.get_system().recovery_indicators(field, eta);
    }

    template <int dim>
    class RecoveryDisplacement
      : public FieldCriterion<dim, recovery_indicators<dim>, false>
    {};

    template <int dim>
    class RecoveryVelocity
      : public FieldCriterion<dim, recovery_indicators<dim>, true>
    {};

    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(
      RecoveryDisplacement,
      "recovery displacement",
      "Zienkiewicz and Zhu's indicator of the displacement, "
      "||G u - grad u|| on each cell with G u the recovered (nodally "
      "averaged) gradient; it sees the jumps Kelly's indicator sees, "
      "without face integrals, at a fraction of its cost")
    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(
      RecoveryVelocity,
      "recovery velocity",
      "Zienkiewicz and Zhu's indicator of the velocity (as recovery "
      "displacement)")
  } // namespace MeshRefinement
} // namespace dyncontact
