#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/core/parameter_file.h>
#include <dyncontact/core/simulator.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/output/output_directory.h>
#include <dyncontact/output/progress.h>
#include <dyncontact/output/reference_states.h>
#include <dyncontact/output/vtu_writer.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  template <int dim>
  Simulator<dim>::Simulator(
    ParameterHandler                                       &prm,
    const std::string                                      &input_directory,
    const MPI_Comm                                          comm,
    const std::vector<std::pair<std::string, std::string>> &set_entries)
    : comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , control(comm, pcout)
    , checkpoints(comm)
  {
    // Each component reads the subsections it owns (parameter_owners())
    // with parse_parameters(prm); what it needs of another owner's is
    // handed to it by name.
    parameters.parse_parameters(prm);
    parameters.input_directory = input_directory;
    time_integration.parse_parameters(prm);
    scheme = &scheme_by_name(time_integration.scheme);
    OutputParameters output;
    output.parse_parameters(prm);
    checkpoints.parse_parameters(prm);
    checkpoints.set_output_directory(parameters.output_directory);
    SimulationControl::Parameters intervals;
    intervals.output_interval    = output.output_interval;
    intervals.checkpoint_steps   = checkpoints.interval_in_steps();
    intervals.checkpoint_minutes = checkpoints.interval_in_minutes();
    control.parse_parameters(time_integration, intervals, scheme->is_static);

    typename DiscreteProblem<dim>::Parameters discretization;
    discretization.system.degree      = parameters.degree;
    discretization.system.lumped_mass = time_integration.lumped_mass;
    discretization.system.consistent_mass_fraction =
      time_integration.consistent_mass_fraction;
    discretization.numerical_dissipation =
      time_integration.numerical_dissipation;
    discretization.serial_triangulation = parameters.serial_triangulation;
    problem = std::make_unique<DiscreteProblem<dim>>(*scheme,
                                                     discretization,
                                                     pcout,
                                                     comm);
    problem->parse_parameters(prm);
    mesh_adaptor = std::make_unique<MeshAdaptor<dim>>();
    mesh_adaptor->parse_parameters(prm);
    time_integration.check_mass_fraction(parameters.degree,
                                         mesh_adaptor->adapts_during_run());
    control.set_refinement_interval(mesh_adaptor->get_refinement_interval());

    vtu_writer       = std::make_unique<VtuWriter<dim>>(output);
    reference_states = std::make_unique<ReferenceStates<dim>>();
    reference_states->parse_parameters(prm);
    postprocessors = std::make_unique<Postprocess::Manager<dim>>();
    postprocessors->parse_parameters(prm);
    progress = std::make_unique<Progress>(output.progress_interval, pcout);
    scene    = create_scene<dim>(prm,
                              input_directory,
                              parameters.degree,
                              problem->assembles_step_matrix());
    problem->get_contact().check(*scene);
    if (!scene->input_checksum().empty())
      checkpoints.add_critical_parameter(scene->subsection() +
                                           "/(checksum of the input files)",
                                         scene->input_checksum());
    reference_states->constrain(control);
    mesh_adaptor->initialize_simulator(*this);
    vtu_writer->initialize_simulator(*this);
    reference_states->initialize_simulator(*this);
    postprocessors->initialize_simulator(*this);
    run_report.initialize_simulator(*this);
    warn_of_unread_entries(set_entries);
  }



  template <int dim>
  Simulator<dim>::~Simulator() = default;



  template <int dim>
  void
  Simulator<dim>::start()
  {
    problem->setup(*scene, *timer);
    // before t = 0: refine the contact zone of the initial state
    mesh_adaptor->refine_initial_contact_zone(*problem, *timer);
    // the slave sides of the mesh at t = 0 stay when the mesh adapts
    problem->get_contact().keep_slave_sides();
    control.reset(problem->get_contact().get_rows().size());
    problem->start(*scene, control.get_timestep(), *timer);
    record_statistics();
  }



  template <int dim>
  void
  Simulator<dim>::open_outputs()
  {
    // (from here on a failure leaves this run's files: its summary says so)
    outputs_open = true;
    postprocessors->open_file(parameters.output_directory + "/statistics.tsv");
    run_report.remove_earlier_summary();
    vtu_writer->remove_later_files();
    if (vtu_writer->is_enabled() && !checkpoints.resume())
      {
        // the initial state: after a first step, the start of that step
        const bool after_step = control.get_step() > 0;
        if (after_step)
          problem->swap_with_initial_state();
        vtu_writer->write(0.);
        if (after_step)
          problem->swap_with_initial_state();
      }
  }



  template <int dim>
  void
  Simulator<dim>::resume()
  {
    const std::string dir   = checkpoints.last_directory();
    const auto        state = checkpoints.read_state(dir);
    postprocessors->load(state);
    DiscreteProblem<dim> &p = *problem;
    p.load_mesh(Checkpoints::mesh_file(dir));
    p.get_contact().load(state);
    p.setup(*scene, *timer);
    if (state.count("contact_slave_sides") == 0)
      // a checkpoint of a version that chose them anew at every set-up:
      // those of the checkpoint's mesh are kept from now on
      p.get_contact().keep_slave_sides();
    VectorType              flags;
    std::vector<VectorType> controller_vectors(
      control.n_checkpoint_vectors(state));
    p.load(Checkpoints::mesh_file(dir), flags, controller_vectors);
    control.load(state, p.get_contact().get_rows(), flags, controller_vectors);
    // (loads that change in time: those of the checkpoint's time)
    p.set_load_time(control.get_time());
    vtu_writer->load(state);
    mesh_adaptor->load(state);
    if (state.count("refinement_pending") &&
        state.at("refinement_pending") == "1")
      {
        // the run ended on a step after which the mesh adapts: adapt now, as
        // the uninterrupted run did (the active sets refer to the old mesh),
        // with the last step's active sets (Contact zone/Keep distance)
        p.restore_reported_active_sets(flags);
        refine_mesh();
      }
    // (unless the adaptation changed the mesh)
    p.resume_integrator(control.get_timestep(), flags, *timer);
    if (control.is_adaptive() && state.count("step_matrices_built"))
      // those of the run before the checkpoint; the integrator made above
      // built one more, which counts
      p.set_n_earlier_step_matrices(
        std::stoul(state.at("step_matrices_built")));
    open_outputs();
    pcout << "   resumed from " << dir << " at step " << control.get_step()
          << ", t = " << control.get_time() << " s" << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::record_statistics()
  {
    postprocessors->execute(*timer);
    {
      TimerOutput::Scope t(*timer, "diagnostics");
      postprocessors->check_last_row();
    }
    if (reference_states->writes())
      {
        TimerOutput::Scope t(*timer, "reference states");
        reference_states->write(control.get_time());
      }
    mesh_adaptor->clear_record();
  }



  template <int dim>
  void
  Simulator<dim>::refine_mesh()
  {
    if (mesh_adaptor->adapt(*problem, control.get_timestep(), *timer))
      // the estimates and the rows' states refer to the old mesh
      control.reset(problem->get_contact().get_rows().size());
  }



  template <int dim>
  std::string
  Simulator<dim>::write_checkpoint()
  {
    TimerOutput::Scope t(*timer, "checkpoint");
    const std::string  dir = checkpoints.begin(control.get_step());
    std::map<std::string, std::string> state;
    DiscreteProblem<dim>              &p     = *problem;
    VectorType                         flags = p.active_set_flags();
    const std::vector<VectorType>      controller_vectors =
      control.save(state, p.get_contact().get_rows(), flags);
    p.save(Checkpoints::mesh_file(dir), flags, controller_vectors);
    postprocessors->save(state);
    mesh_adaptor->save(state);
    vtu_writer->save(state);
    p.get_contact().save(state);
    // the last step of a run does not adapt the mesh: a resumed run does
    state["refinement_pending"] =
      moments.last && control.refinement_due(control.get_step()) ? "1" : "0";
    state["step_matrices_built"] = std::to_string(p.n_step_matrices());
    checkpoints.finish(dir, state);
    return dir;
  }



  template <int dim>
  void
  Simulator<dim>::stop_after_failed_step(const bool finite)
  {
    const StepReport &report = problem->get_report();
    const std::string cause =
      problem->failure_cause(control.get_timestep(),
                             finite && !report.converged() ?
                               report.failure() :
                               "the solution is not finite");
    std::ostringstream message;
    if (control.get_step() == 0 && !checkpoints.resume())
      {
        // nothing to keep: the output directory stays as it was
        message << std::setprecision(6)
                << "the first step (tau = " << control.get_timestep()
                << " s) failed: " << cause
                << ". Nothing was written. Try a smaller Time integration/Time "
                   "step, or set 'Time integration/Time step adaptation = "
                   "true'.";
        AssertThrow(false, ExcMessage(message.str()));
      }
    const std::string dir = write_checkpoint();
    message << std::setprecision(6) << "step " << control.get_step() + 1
            << " (from t = " << control.get_time()
            << " s, tau = " << control.get_timestep() << " s) failed: " << cause
            << ". The last good state (step " << control.get_step()
            << ") is the checkpoint '" << dir
            << "' (resume with 'Checkpointing/Resume = true'), or set 'Time "
               "integration/Time step adaptation = true'.";
    AssertThrow(false, ExcMessage(message.str()));
    std::abort();
  }



  template <int dim>
  void
  Simulator<dim>::run_time_loop()
  {
    pcout << "dyncontact: scene '" << scene->name() << "', " << dim
          << "D, scheme " << scheme->name << ", "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
          << (parameters.serial_triangulation ? ", serial triangulation" : "")
          << std::endl;
    // the output directory must be writable; nothing in it is touched
    // before the setup has succeeded
    output_directory = std::make_unique<OutputDirectory>(
      parameters.output_directory,
      std::vector<std::string>{"statistics.tsv",
                               RunReport<dim>::file_name,
                               "solution.pvd",
                               "checkpoints/"},
      comm);
    problem->build_mesh(*scene,
                        parameters.initial_refinements,
                        checkpoints.resume(),
                        *timer);
    if (checkpoints.resume())
      resume();
    else
      start();
    pcout << run_report.banner() << std::endl;
    progress->start();
    loop_clock.restart();

    while (control.keep_going())
      {
        Timer      step_timer;
        const auto outcome = control.advance(*problem, *timer);
        if (outcome.failed)
          stop_after_failed_step(outcome.finite);
        moments = outcome.moments;
        step_timer.stop();
        step_wall_time = step_timer.wall_time();
        record_statistics();
        if (!outputs_open)
          open_outputs();
        const StepReport &report = problem->get_report();
        progress->step(
          control.get_step(),
          control.get_time(),
          control.get_end_time(),
          report.tau,
          control.steps_to_end(report.tau),
          Utilities::MPI::sum<types::global_dof_index>(
            std::count(report.active.begin(), report.active.end(), 1), comm),
          problem->get_contact().n_global_rows(),
          report.displacement_solve.iterations,
          report.displacement_solve.linear_iterations +
            report.projection_solve.linear_iterations);
        if (moments.output && vtu_writer->is_enabled())
          vtu_writer->write(control.get_time());
        if (moments.refinement)
          refine_mesh();
        if (moments.checkpoint)
          write_checkpoint();
      }
    if (!outputs_open)
      open_outputs();
    loop_clock.stop();
    run_report.write_summary(run_clock.wall_time(),
                             loop_clock.wall_time(),
                             problem->n_step_matrices(),
                             [this](const SummaryInput &input) {
                               return postprocessors->summary(input);
                             });
  }



  template <int dim>
  Statistics
  Simulator<dim>::run()
  {
    // created here, not in the constructor: a TimerOutput destroyed while
    // an exception unwinds prints an MPI warning over the user's message
    timer = std::make_unique<TimerOutput>(comm,
                                          pcout,
                                          TimerOutput::never,
                                          TimerOutput::wall_times);
    try
      {
        run_time_loop();
      }
    catch (const std::exception &e)
      {
        // TimerOutput would otherwise print an MPI warning while the
        // exception unwinds; the user gets the exception's message instead
        timer.reset();
        // this run's files have begun: its summary says that it failed
        // (before, the output directory is as the earlier run left it)
        if (outputs_open)
          run_report.write_failed_summary(message_of(e));
        throw;
      }
    catch (...)
      {
        timer.reset();
        if (outputs_open)
          run_report.write_failed_summary("an unknown error");
        throw;
      }
    return postprocessors->get_statistics();
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace dyncontact
