#include <deal.II/base/mpi.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/base/global_parameters.h>
#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/output/run_report.h>
#include <dyncontact/output/summary.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/integrators.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  template <int dim>
  std::string
  RunReport<dim>::banner() const
  {
    const MPI_Comm                 comm       = this->get_mpi_communicator();
    const SemiDiscreteSystem<dim> &system     = this->get_system();
    const Scene<dim>              &scene      = this->get_scene();
    const ContactSetup<dim>       &contact    = this->get_contact();
    const TimeIntegrator          &integrator = this->get_integrator();
    const SimulationControl       &control    = this->get_control();
    // DoFs per body
    std::vector<types::global_dof_index> body_dofs;
    for (const auto n : system.n_locally_owned_body_dofs())
      body_dofs.push_back(Utilities::MPI::sum(n, comm));
    std::ostringstream text;
    text << std::setprecision(6) << "   bodies: " << body_dofs.size() << " (";
    for (unsigned int b = 0; b < body_dofs.size(); ++b)
      text << (b > 0 ? ", " : "") << "body " << b + 1 << ": " << body_dofs[b]
           << " DoFs";
    text << ")\n   contact: ";
    if (!scene.has_contact())
      text << "none (no rows, no contact search)";
    else if (const std::size_t n_pairs = scene.contact_pairs().size(),
             n_obstacles               = scene.obstacles().size();
             n_pairs == 0)
      text << (n_obstacles == 1 ?
                 std::string("rigid obstacle") :
                 std::to_string(n_obstacles) + " rigid obstacles")
           << " (no contact search), " << contact.n_global_rows() << " rows";
    else if (n_pairs == 1 && n_obstacles == 0)
      text << "two bodies through phi_h, " << contact.n_global_rows()
           << " rows on the slave side";
    else
      text << n_pairs << " pair" << (n_pairs > 1 ? "s" : "")
           << " of bodies through phi_h"
           << (n_obstacles == 1 ? " and a rigid obstacle" :
               n_obstacles > 1  ? " and " + std::to_string(n_obstacles) +
                                   " rigid obstacles" :
                                 "")
           << ", " << contact.n_global_rows() << " rows";
    text << "\n   material: "
         << (system.is_viscous() ?
               "viscoelastic (Kelvin-Voigt, viscous form B)" :
               "elastic (no viscous form)")
         << ", " << system.mass_description() << " mass\n";
    // each body's material where they differ
    if (!scene.one_material())
      for (unsigned int b = 0; b < scene.n_bodies(); ++b)
        {
          const Material &m = scene.material(b);
          text << "     body " << b + 1 << ": E = " << m.youngs_modulus
               << " Pa, nu = " << m.poissons_ratio << ", rho = " << m.density
               << " kg/m^3";
          if (m.is_viscous())
            text << ", mu_v = " << m.viscous_shear_modulus
                 << " Pa s, lambda_v = " << m.viscous_lambda << " Pa s";
          text << "\n";
        }
    text << "   solver: active set, CG with "
         << integrator.preconditioner_name()
         << (integrator.matrix_free() ? " on the matrix-free step operator" :
                                        "");
    if (integrator.matrix_free())
      text << " (largest S_ii/M_ii " << std::setprecision(3)
           << integrator.inertia_ratio() << std::setprecision(6) << ")";
    else if (const double bound = integrator.condition_bound();
             std::isfinite(bound))
      text << " (condition number of S scaled by its diagonal at most "
           << std::setprecision(3) << bound << std::setprecision(6) << ")";
    text << "\n   time: ";
    std::string scheme = "scheme " + integrator.get_scheme().name;
    if (const double theta = integrator.get_operators().numerical_dissipation();
        theta > 0.)
      {
        std::ostringstream value; // 6 digits, as the rest of the banner
        value << theta;
        scheme += " with numerical dissipation theta = " + value.str();
      }
    if (integrator.get_scheme().is_static)
      text << "static problem (one solve)";
    else if (control.is_adaptive())
      text << scheme << ", adaptive tau in [" << control.get_minimum_timestep()
           << ", " << control.get_maximum_timestep() << "] s, now "
           << control.get_timestep() << " s, from t = " << control.get_time()
           << " to " << control.get_end_time() << " s";
    else
      {
        const double tau     = control.get_timestep();
        const double n_steps = control.steps_to_end(tau);
        const double last    = control.get_time() + n_steps * tau;
        text << scheme << ", tau = " << tau << " s, " << n_steps
             << " steps from t = " << control.get_time() << " to " << last
             << " s";
        if (last > control.get_end_time() + control.end_time_tolerance())
          text << "\n   warning: End time = " << control.get_end_time()
               << " s is not reached in whole steps of Time step = " << tau
               << " s: the last step ends at t = " << last
               << " s. Choose End time as a multiple of Time step, or 'Time "
                  "step control = adaptive' (its last step ends at End time).";
      }
    return text.str();
  }



  template <int dim>
  void
  RunReport<dim>::write_summary(
    const double                                            wall_time,
    const double                                            loop_wall_time,
    const unsigned int                                      step_matrices,
    const std::function<std::string(const SummaryInput &)> &statistics_lines)
    const
  {
    const TimeIntegrator    &integrator = this->get_integrator();
    const SimulationControl &control    = this->get_control();
    SummaryInput             input;
    input.dim       = dim;
    input.is_static = integrator.get_scheme().is_static;
    input.energy_tolerance =
      integrator.get_operators().get_solver_parameters().energy_tolerance();
    input.wall_time      = wall_time;
    input.loop_wall_time = loop_wall_time;
    input.section_wall_times =
      this->get_timer().get_summary_data(TimerOutput::total_wall_time);
    input.section_calls =
      this->get_timer().get_summary_data(TimerOutput::n_calls);
    input.adaptive_time_steps = control.is_adaptive();
    input.located_events      = control.n_located_events();
    input.repeated_steps      = control.n_repeated_steps();
    input.passed_output_times = control.n_passed_output_times();
    input.step_matrices       = step_matrices;
    input.preconditioner      = integrator.preconditioner_name();
    input.matrix_free         = integrator.matrix_free();
    input.inertia_ratio       = integrator.inertia_ratio();
    input.condition_bound     = integrator.condition_bound();
    input.ranks_and_mesh      = std::to_string(Utilities::MPI::n_mpi_processes(
                             this->get_mpi_communicator())) +
                           " MPI rank(s), " +
                           (this->get_parameters().serial_triangulation ?
                              "serial triangulation" :
                              "distributed triangulation (p4est)");
    const std::string text =
      summary_text(this->get_statistics(), input, statistics_lines(input));
    const std::string file =
      this->get_parameters().output_directory + "/" + file_name;
    std::string failure;
    if (Utilities::MPI::this_mpi_process(this->get_mpi_communicator()) == 0)
      {
        errno = 0;
        std::ofstream out(file);
        out << text;
        out.close();
        if (!out.good())
          failure = write_failure(file);
      }
    stop_with_message_of_rank_0(failure, this->get_mpi_communicator());
    this->get_pcout() << "\nSummary (also in " << file << "):\n"
                      << text << std::flush;
  }



  template <int dim>
  void
  RunReport<dim>::remove_earlier_summary() const
  {
    const std::string file =
      this->get_parameters().output_directory + "/" + file_name;
    std::string failure;
    if (Utilities::MPI::this_mpi_process(this->get_mpi_communicator()) == 0)
      {
        std::error_code error;
        std::filesystem::remove(file, error);
        if (error)
          failure = "Cannot remove '" + file +
                    "', the summary of an earlier run: " + error.message() +
                    ".";
      }
    stop_with_message_of_rank_0(failure, this->get_mpi_communicator());
  }



  template <int dim>
  void
  RunReport<dim>::write_failed_summary(
    const std::string &message) const noexcept
  {
    try
      {
        if (Utilities::MPI::this_mpi_process(this->get_mpi_communicator()) != 0)
          return;
        const SimulationControl &control = this->get_control();
        std::ofstream out(this->get_parameters().output_directory + "/" +
                          file_name);
        out << std::setprecision(6) << "run: FAILED after step "
            << control.get_step() << " (t = " << control.get_time()
            << " s); statistics.tsv holds the steps up to there\n"
            << "error: " << message << "\n";
      }
    catch (...)
      {
        // the run's own error is reported; this record is the best effort
      }
  }



  template class RunReport<2>;
  template class RunReport<3>;
} // namespace dyncontact
