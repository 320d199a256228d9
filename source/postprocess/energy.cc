// Energies (Theorem 3.2): E_kin = 1/2 udot^T M udot, E_el = 1/2 u^T A u -
// f^T u, and the viscous dissipation W_visc += (du)^T B (du) / tau,
// accumulated over the steps; E_kin + E_el + W_visc is constant without
// contact and non-increasing with contact.

#include <dyncontact/core/simulation_control.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/time_stepping/integrators.h>

#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class Energy : public Interface<dim>
    {
    public:
      std::vector<std::string>
      columns() const override
      {
        return {"energy_kinetic",
                "energy_elastic",
                "dissipation_viscous",
                "energy_total"};
      }

      void
      execute(std::vector<double> &row) override
      {
        const SemiDiscreteSystem<dim> &system = this->get_system();
        const VectorType              &u      = this->get_solution();
        VectorType                     M_udot(u);
        const auto [kinetic, elastic] =
          system.energies(u, this->get_velocity(), M_udot);
        if (this->get_control().get_step() > 0 && system.has_viscous_matrix())
          {
            VectorType du(u), B_du(u);
            du -= this->get_old_solution();
            system.get_viscous_matrix().vmult(B_du, du);
            dissipation += (B_du * du) / this->get_integrator().time_step();
          }
        row.insert(row.end(),
                   {kinetic, elastic, dissipation, kinetic + elastic});
      }

      void
      save(std::map<std::string, std::string> &state) const override
      {
        std::ostringstream s;
        s << std::setprecision(17) << dissipation;
        state["viscous_dissipation"] = s.str();
      }

      void
      load(const std::map<std::string, std::string> &state) override
      {
        dissipation = std::stod(state.at("viscous_dissipation"));
      }

    private:
      double dissipation = 0.;
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(Energy,
                                      "energy",
                                      10,
                                      "kinetic and elastic energy, viscous "
                                      "dissipation (Theorem 3.2)")
  } // namespace Postprocess
} // namespace dyncontact
