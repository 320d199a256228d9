// The energy of the error, estimated on each cell from Zienkiewicz and
// Zhu's indicators of the displacement and of the velocity: the criterion
// "energy error" (scaled to maximum 1 over all ranks, for the fractions)
// and the estimate that Mesh refinement/Error tolerance marks by (in J).

#include <deal.II/lac/vector.h>

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/interface.h>
#include <dyncontact/scenes/interface.h>

namespace dyncontact
{
  namespace MeshRefinement
  {
    template <int dim>
    void
    energy_error_indicators(const SimulatorAccess<dim> &access,
                            Vector<float>              &eta)
    {
      const SemiDiscreteSystem<dim> &system = access.get_system();
      const Scene<dim>              &scene  = access.get_scene();
      Vector<float>                  ku(eta.size()), kv(eta.size());
      system.recovery_indicators(access.get_solution(), ku);
      system.recovery_indicators(access.get_velocity(), kv);
      for (const auto &cell : system.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const Material    &material = scene.material(cell->material_id());
            const unsigned int i        = cell->active_cell_index();
            const double       h        = cell->diameter();
            eta[i] =
              0.5 * (material.density * h * h * kv[i] * kv[i] +
                     (material.lambda() + 2. * material.mu()) * ku[i] * ku[i]);
          }
    }

    template void
    energy_error_indicators(const SimulatorAccess<2> &, Vector<float> &);
    template void
    energy_error_indicators(const SimulatorAccess<3> &, Vector<float> &);

    template <int dim>
    class EnergyError : public Interface<dim>
    {
    public:
      void
      execute(Vector<float> &indicators) const override
      {
        Vector<float> eta(indicators.size());
        energy_error_indicators(*this, eta);
        add_scaled(eta, indicators, this->get_mpi_communicator());
      }
    };

    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(
      EnergyError,
      "energy error",
      "the energy of the error on each cell, 1/2 rho h^2 k(u_dot)^2 + 1/2 "
      "(lambda + 2 mu) k(u)^2 with k Zienkiewicz and Zhu's indicator (as "
      "recovery displacement and velocity): the elastic and the kinetic "
      "part, so that it sees the waves that carry a body's motion as well "
      "as the strain at the contact (what Error tolerance marks by)")
  } // namespace MeshRefinement
} // namespace dyncontact
