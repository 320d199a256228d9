// The simulator's reports to the user: the banner (what the run uses and
// leaves out) and the summary at the end (also in summary.txt).

#include <deal.II/base/mpi.h>

#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/core/simulator.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/output/summary.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  template <int dim>
  void
  Simulator<dim>::print_banner()
  {
    // DoFs per body
    std::vector<types::global_dof_index> body_dofs;
    for (const auto n : system->n_locally_owned_body_dofs())
      body_dofs.push_back(Utilities::MPI::sum(n, comm));
    std::ostringstream text;
    text << std::setprecision(6) << "   bodies: " << body_dofs.size() << " (";
    for (unsigned int b = 0; b < body_dofs.size(); ++b)
      text << (b > 0 ? ", " : "") << "body " << b + 1 << ": " << body_dofs[b]
           << " DoFs";
    text << ")\n   contact: ";
    if (!scene->has_contact())
      text << "none (no rows, no contact search)";
    else if (scene->obstacle())
      text << "rigid obstacle (no contact search), " << contact->n_global_rows()
           << " rows";
    else
      text << "two bodies through phi_h, " << contact->n_global_rows()
           << " rows on the slave side";
    text << "\n   material: "
         << (system->is_viscous() ?
               "viscoelastic (Kelvin-Voigt, viscous form B)" :
               "elastic (no viscous form)")
         << ", " << (system->matrices().lumped_mass() ? "lumped" : "consistent")
         << " mass\n   solver: active set, CG with "
         << (integrator->uses_amg() ? "AMG" : "Jacobi");
    if (const double bound = integrator->condition_bound();
        std::isfinite(bound))
      text << " (condition number of S scaled by its diagonal at most "
           << std::setprecision(3) << bound << std::setprecision(6) << ")";
    text << "\n   time: ";
    if (scheme.is_static)
      text << "static problem (one solve)";
    else if (time_step_controller.is_adaptive())
      text << "scheme " << scheme.name << ", adaptive tau in ["
           << time_step_controller.get_minimum_timestep() << ", "
           << time_step_controller.get_maximum_timestep() << "] s, now "
           << time_step_controller.get_timestep()
           << " s, from t = " << control.get_time() << " to "
           << control.get_end_time() << " s";
    else
      {
        const double tau = time_step_controller.get_timestep();
        const double n_steps =
          std::ceil((control.get_end_time() - control.get_time()) / tau - 1e-9);
        const double last = control.get_time() + n_steps * tau;
        text << "scheme " << scheme.name << ", tau = " << tau << " s, "
             << n_steps << " steps from t = " << control.get_time() << " to "
             << last << " s";
        if (last > control.get_end_time() + 1e-9 * tau)
          text << "\n   warning: End time = " << control.get_end_time()
               << " s is not reached in whole steps of Time step = " << tau
               << " s: the last step ends at t = " << last
               << " s. Choose End time as a multiple of Time step, or 'Time "
                  "step control = adaptive' (its last step ends at End time).";
      }
    pcout << text.str() << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::write_summary()
  {
    SummaryInput input;
    input.dim              = dim;
    input.is_static        = scheme.is_static;
    input.energy_tolerance = solver_parameters.energy_tolerance();
    input.wall_time        = run_clock.wall_time();
    input.loop_wall_time   = loop_clock.wall_time();
    input.section_wall_times =
      timer->get_summary_data(TimerOutput::total_wall_time);
    input.section_calls       = timer->get_summary_data(TimerOutput::n_calls);
    input.adaptive_time_steps = time_step_controller.is_adaptive();
    input.located_events      = time_step_controller.n_located_events();
    input.repeated_steps      = time_step_controller.n_repeated_steps();
    input.step_matrices =
      n_step_matrices + integrator->get_operators().n_step_matrices_built;
    input.uses_amg        = integrator->uses_amg();
    input.condition_bound = integrator->condition_bound();
    const std::string text =
      summary_text(postprocessors->get_statistics(), input);
    const std::string file = parameters.output_directory + "/summary.txt";
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream out(file);
        out << text;
      }
    pcout << "\nSummary (also in " << file << "):\n" << text << std::flush;
  }



  template void
  Simulator<2>::print_banner();
  template void
  Simulator<3>::print_banner();
  template void
  Simulator<2>::write_summary();
  template void
  Simulator<3>::write_summary();
} // namespace dyncontact
