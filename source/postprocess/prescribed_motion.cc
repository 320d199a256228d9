// The force of the Dirichlet boundaries that move on the bodies
// (Scene::prescribed_displacements()): the sum over their DoFs of the
// residual of the displacement step, scaled as the contact force (eq. 13),
// per component; the force-displacement curve of a punch, a support that
// shakes. (Their work is in the energy balance, column work_prescribed.)

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/integrators.h>
#include <dyncontact/time_stepping/simulation_control.h>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class PrescribedMotionForce : public Interface<dim>
    {
    public:
      bool
      applies() const override
      {
        return !this->get_scene().prescribed_displacements().empty();
      }

      std::vector<std::string>
      columns() const override
      {
        std::vector<std::string> names;
        for (const std::string c : {"x", "y", "z"})
          if (names.size() < dim)
            names.push_back("prescribed_force_" + c);
        return names;
      }

      void
      execute(std::vector<double> &row) override
      {
        std::vector<double> force(dim, 0.);
        // (at t = 0 and in a static problem's start: no step yet)
        const VectorType &reaction =
          this->get_integrator().get_operators().prescribed_reaction();
        if (this->get_control().get_step() > 0 && reaction.size() > 0)
          {
            const std::vector<unsigned char> &slots =
              this->get_system().get_owned_dof_slots();
            const double *r = reaction.begin();
            for (std::size_t k = 0; k < slots.size(); ++k)
              force[slots[k] % dim] += r[k];
          }
        Utilities::MPI::sum(force, this->get_mpi_communicator(), force);
        row.insert(row.end(), force.begin(), force.end());
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(PrescribedMotionForce,
                                      "prescribed force",
                                      "force of the Dirichlet boundaries "
                                      "that move on the bodies")
  } // namespace Postprocess
} // namespace dyncontact
