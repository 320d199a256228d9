// The error in the physical energy norm against the scene's exact solution
// (eqs. 22-24): ||(e, edot)||_E^2 = 1/2 ||edot||^2_{L2(rho)} + 1/2 a(e, e).

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <dyncontact/discretization/energy_density.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <cmath>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class ErrorNorm : public Interface<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Postprocess");
        prm.enter_subsection("Error energy norm");
        prm.declare_entry(
          "Interval",
          "output times",
          Patterns::Selection("output times|every step"),
          "When the energy-norm error against the exact solution is "
          "integrated (it costs about as much as a time step in 3D): at the "
          "output times (every Output/Output interval, whether or not VTU "
          "files are written), the first and the last step, with nan in "
          "the column between them; or every step (for the maximum over "
          "time).");
        prm.leave_subsection();
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Postprocess");
        prm.enter_subsection("Error energy norm");
        every_step = (prm.get("Interval") == "every step");
        prm.leave_subsection();
        prm.leave_subsection();
      }

      /// (not for a static problem: the exact solutions are those of the
      /// dynamics, at a time a static solve does not have)
      bool
      applies() const override
      {
        return this->get_scene().has_exact_solution() &&
               !this->get_control().is_static_problem();
      }

      std::string
      summary(const Statistics &s, const SummaryInput &) const override
      {
        return error_summary(s, "error_energy_norm");
      }


      std::vector<std::string>
      columns() const override
      {
        return {"error_energy_norm"};
      }

      bool
      sampled() const override
      {
        return !every_step;
      }

      /// At the output times (the last step is one), and the first step.
      bool
      due() const override
      {
        return every_step || this->get_control().get_step() == 0 ||
               this->get_moments().output;
      }

      bool
      is_norm() const override
      {
        return true;
      }

      void
      execute(std::vector<double> &row) override
      {
        const SemiDiscreteSystem<dim> &system = this->get_system();
        const Scene<dim>              &scene  = this->get_scene();
        const double                   time   = this->get_control().get_time();
        const MPI_Comm                 comm   = this->get_mpi_communicator();
        // The exact solution has kinks and jumps inside cells: an iterated
        // Gauss rule integrates them robustly if none of its points is
        // rational. A Gauss rule with an odd number of points has the
        // midpoint, and iterated twice it has points at 1/4 and 3/4 of the
        // cell, where a front moving h/(2p) per step (tau = h/(2pc), p even)
        // lands at some steps (every other one for p = 2, every fourth for
        // p = 4): the exact solution would be sampled on either side of its
        // jump, by the last bits of t and x. So the number of points is
        // even: p + 1 for odd p, p + 2 for even p.
        const unsigned int   degree = system.get_fe().degree;
        const QIterated<dim> quadrature(QGauss<1>(degree % 2 == 1 ? degree + 1 :
                                                                    degree + 2),
                                        2);
        FEValues<dim>        fe_values(this->get_mapping(),
                                system.get_fe(),
                                quadrature,
                                update_values | update_gradients |
                                  update_quadrature_points | update_JxW_values);
        const VectorType     u_ghosted = system.ghosted(this->get_solution());
        const VectorType     v_ghosted = system.ghosted(this->get_velocity());

        const FEValuesExtractors::Vector displacement(0);
        std::vector<Tensor<1, dim>>      vh(quadrature.size());
        std::vector<Tensor<2, dim>>      grad_uh(quadrature.size());
        double                           local = 0.;
        for (const auto &cell :
             system.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const Material &material = scene.material(cell->material_id());
              fe_values.reinit(cell);
              fe_values[displacement].get_function_values(v_ghosted, vh);
              fe_values[displacement].get_function_gradients(u_ghosted,
                                                             grad_uh);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  const ExactValues<dim> exact =
                    scene.exact_solution(fe_values.quadrature_point(q), time);
                  const Tensor<1, dim> edot = exact.velocity - vh[q];
                  local +=
                    energy_density(material,
                                   edot,
                                   exact.displacement_gradient - grad_uh[q]) *
                    fe_values.JxW(q);
                }
            }
        row.push_back(std::sqrt(Utilities::MPI::sum(local, comm)));
      }

    private:
      bool every_step = false;
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(ErrorNorm,
                                      "error energy norm",
                                      "energy-norm error against the exact "
                                      "solution (eqs. 22-24)")
  } // namespace Postprocess
} // namespace dyncontact
