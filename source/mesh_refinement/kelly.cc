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
    /// Adds the scaled Kelly indicators of @p field.
    template <int dim>
    void
    add_kelly_indicators(const SimulatorAccess<dim> &access,
                         const VectorType           &field,
                         Vector<float>              &indicators)
    {
      const SemiDiscreteSystem<dim> &system  = access.get_system();
      const VectorType               ghosted = system.ghosted(field);
      Vector<float>                  kelly(indicators.size());
      KellyErrorEstimator<dim>::estimate(access.get_mapping(),
                                         system.get_dof_handler(),
                                         QGauss<dim - 1>(
                                           system.get_fe().degree + 1),
                                         {},
                                         ghosted,
                                         kelly);
      add_scaled(kelly, indicators, access.get_mpi_communicator());
    }



    template <int dim>
    class KellyDisplacement : public Interface<dim>
    {
    public:
      void
      execute(Vector<float> &indicators) const override
      {
        add_kelly_indicators(*this, this->get_solution(), indicators);
      }
    };



    template <int dim>
    class KellyVelocity : public Interface<dim>
    {
    public:
      void
      execute(Vector<float> &indicators) const override
      {
        add_kelly_indicators(*this, this->get_velocity(), indicators);
      }
    };

    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(KellyDisplacement,
                                             "kelly displacement",
                                             10,
                                             "Kelly's indicator of the "
                                             "displacement")
    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(KellyVelocity,
                                             "kelly velocity",
                                             20,
                                             "Kelly's indicator of the "
                                             "velocity")
  } // namespace MeshRefinement
} // namespace dyncontact
