// Zienkiewicz and Zhu's gradient-recovery indicators of the displacement or
// of the velocity, scaled to maximum 1 over all ranks.

#include <deal.II/lac/vector.h>

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/interface.h>

namespace dyncontact
{
  namespace MeshRefinement
  {
    /// Adds the scaled recovery indicators of @p field.
    template <int dim>
    void
    add_recovery_indicators(const SimulatorAccess<dim> &access,
                            const VectorType           &field,
                            Vector<float>              &indicators)
    {
      Vector<float> eta(indicators.size());
      access.get_system().recovery_indicators(field, eta);
      add_scaled(eta, indicators, access.get_mpi_communicator());
    }



    template <int dim>
    class RecoveryDisplacement : public Interface<dim>
    {
    public:
      void
      execute(Vector<float> &indicators) const override
      {
        add_recovery_indicators(*this, this->get_solution(), indicators);
      }
    };



    template <int dim>
    class RecoveryVelocity : public Interface<dim>
    {
    public:
      void
      execute(Vector<float> &indicators) const override
      {
        add_recovery_indicators(*this, this->get_velocity(), indicators);
      }
    };

    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(
      RecoveryDisplacement,
      "recovery displacement",
      24,
      "Zienkiewicz and Zhu's indicator of the displacement, "
      "||G u - grad u|| on each cell with G u the recovered (nodally "
      "averaged) gradient; it sees the jumps Kelly's indicator sees, "
      "without face integrals, at a fraction of its cost")
    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(
      RecoveryVelocity,
      "recovery velocity",
      26,
      "Zienkiewicz and Zhu's indicator of the velocity (as recovery "
      "displacement)")
  } // namespace MeshRefinement
} // namespace dyncontact
