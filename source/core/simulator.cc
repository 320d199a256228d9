#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/base/memory_check.h>
#include <dyncontact/base/vector_copy.h>
#include <dyncontact/contact/contact_setup.h>
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
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dyncontact
{
  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler  &prm,
                            const std::string &input_directory,
                            const MPI_Comm     comm)
    : comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , control(comm, time_step_controller)
    , scheme(TimeIntegrator::parse_scheme(prm))
    , triangulation(comm)
  {
    parameters.parse_parameters(prm);
    parameters.input_directory = input_directory;
    control.parse_parameters(prm, scheme.is_static);
    time_step_controller.parse_parameters(prm,
                                          scheme.is_static,
                                          control.get_end_time());
    solver_parameters.parse_parameters(prm);
    typename SemiDiscreteSystem<dim>::Parameters system_parameters;
    system_parameters.parse_parameters(prm);
    system = std::make_unique<SemiDiscreteSystem<dim>>(system_parameters,
                                                       mapping,
                                                       comm);
    typename ContactSetup<dim>::Parameters contact_parameters;
    contact_parameters.parse_parameters(prm);
    contact = std::make_unique<ContactSetup<dim>>(contact_parameters, comm);
    mesh_adaptor = std::make_unique<MeshAdaptor<dim>>();
    mesh_adaptor->parse_parameters(prm);
    vtu_writer = std::make_unique<VtuWriter<dim>>();
    vtu_writer->parse_parameters(prm);
    reference_states = std::make_unique<ReferenceStates<dim>>();
    reference_states->parse_parameters(prm);
    checkpoints.parse_parameters(prm, parameters.output_directory, comm);
    postprocessors = std::make_unique<Postprocess::Manager<dim>>();
    postprocessors->parse_parameters(prm);
    Progress::Parameters progress_parameters;
    progress_parameters.parse_parameters(prm);
    progress = std::make_unique<Progress>(progress_parameters, pcout);
    scene    = create_scene<dim>(prm, input_directory);
    contact->check(*scene);
    if (!scene->input_checksum().empty())
      checkpoints.add_critical_parameter(scene->subsection() +
                                           "/(checksum of the input files)",
                                         scene->input_checksum());
    AssertThrow(!(mesh_adaptor->adapts_during_run() &&
                  (reference_states->writes() || reference_states->compares())),
                ExcMessage(
                  "Reference solutions need the same mesh in both "
                  "runs: they cannot be combined with adaptive "
                  "meshes (Mesh refinement/Refinement interval > 0)."));

    mesh_adaptor->initialize_simulator(*this);
    vtu_writer->initialize_simulator(*this);
    reference_states->initialize_simulator(*this);
    postprocessors->initialize_simulator(*this);
    run_report.initialize_simulator(*this);
  }



  template <int dim>
  Simulator<dim>::~Simulator() = default;



  template <int dim>
  void
  Simulator<dim>::build_mesh()
  {
    TimerOutput::Scope t(*timer, "setup: mesh");
    dyncontact::build_mesh(*scene,
                           triangulation,
                           parameters.initial_refinements,
                           system->get_fe().degree,
                           checkpoints.resume());
  }



  template <int dim>
  void
  Simulator<dim>::setup_discretization()
  {
    {
      TimerOutput::Scope t(*timer, "setup: DoFs and sparsity");
      system->setup(triangulation, *scene);
      // the dynamic sparsity pattern's rows
      release_freed_memory();
      pcout << "   cells: " << triangulation.n_global_active_cells()
            << ", DoFs: " << system->get_dof_handler().n_dofs() << std::endl;
    }
    {
      TimerOutput::Scope t(*timer, "assembly");
      system->assemble(*scene);
    }
    TimerOutput::Scope t(*timer, "contact rows");
    contact->setup(*scene, *system, mapping, pcout);
  }



  template <int dim>
  void
  Simulator<dim>::make_integrator()
  {
    TimerOutput::Scope t(*timer, "setup: step matrix and preconditioner");
    if (integrator)
      n_step_matrices += integrator->get_operators().n_step_matrices_built;
    ActiveSetSolver::NearNullSpace near_null_space;
    near_null_space.translations = system->get_constant_modes();
    if (solver_parameters.amg_rotations)
      near_null_space.rotations = system->rotation_modes();
    integrator =
      std::make_unique<TimeIntegrator>(scheme,
                                       time_step_controller.get_timestep(),
                                       system->matrices(),
                                       solver_parameters,
                                       system->locally_owned_dofs(),
                                       system->locally_relevant_dofs(),
                                       system->get_constraints(),
                                       contact->get_rows(),
                                       near_null_space,
                                       comm);
    // ML's temporaries
    release_freed_memory();
    check_inertia();
  }



  template <int dim>
  void
  Simulator<dim>::check_inertia()
  {
    if (warned_inertia)
      return;
    const std::string warning = integrator->inertia_warning();
    warned_inertia            = !warning.empty();
    pcout << warning;
  }



  template <int dim>
  void
  Simulator<dim>::start()
  {
    setup_discretization();
    // before t = 0: refine the contact zone of the initial state
    for (unsigned int k = 0; k < mesh_adaptor->n_initial_refinements(); ++k)
      {
        system->interpolate_initial_values(*scene, u, udot);
        mesh_adaptor->mark_contact_zone();
        triangulation.execute_coarsening_and_refinement();
        setup_discretization();
      }
    system->interpolate_initial_values(*scene, u, udot);
    time_step_controller.reset(contact->get_rows().size());
    make_integrator();

    // an initially penetrating configuration (allowed only with 'Initial
    // penetration = project'): the M-projection onto K_h
    double largest = 0.;
    for (const double v : contact->get_row_operator().constraint_values(u))
      largest = std::max(largest, v);
    largest = Utilities::MPI::max(largest, comm);
    if (largest > 1e-12)
      {
        integrator->project_onto_constraints(u);
        pcout << "   warning: the initial configuration penetrated by up to "
              << largest << " m; the initial displacement was projected onto "
              << "K_h." << std::endl;
      }
    {
      TimerOutput::Scope t(*timer, "time step");
      report =
        integrator->initialize(time_step_controller.get_timestep(), u, udot);
    }
    AssertThrow(report.converged(),
                ExcMessage("The initial velocity of " + scheme.name +
                           " (eq. 12c) could not be computed: " +
                           report.failure() + "."));
    initial_report = report;
    record_statistics();
  }



  template <int dim>
  void
  Simulator<dim>::open_outputs()
  {
    postprocessors->open_file(parameters.output_directory + "/statistics.tsv");
    if (vtu_writer->is_enabled() && !checkpoints.resume())
      {
        // the initial state: after a first step u_old, udot_old and the
        // initial report
        const bool after_step = control.get_step() > 0;
        auto       swap_state = [&]() {
          if (after_step)
            {
              std::swap(u, u_old);
              std::swap(udot, udot_old);
              std::swap(report, initial_report);
            }
        };
        swap_state();
        vtu_writer->write(0.);
        swap_state();
      }
    outputs_open = true;
  }



  template <int dim>
  void
  Simulator<dim>::resume()
  {
    const std::string dir   = checkpoints.last_directory();
    const auto        state = checkpoints.read_state(dir);
    postprocessors->load(state);
    triangulation.load(Checkpoints::mesh_file(dir));
    setup_discretization();
    VectorType              flags;
    std::vector<VectorType> controller_vectors(
      time_step_controller.n_checkpoint_vectors(state));
    std::vector<VectorType *> vectors = {&u, &udot, &flags};
    for (VectorType &v : controller_vectors)
      vectors.push_back(&v);
    system->deserialize(vectors);
    control.load(state);
    AssertThrow(control.get_end_time() > control.get_time(),
                ExcMessage("Time integration/End time = " +
                           format_number(control.get_end_time()) +
                           " s is not after the checkpoint's time t = " +
                           format_number(control.get_time()) +
                           " s: a resumed run needs a later End time."));
    time_step_controller.load(state,
                              contact->get_rows(),
                              flags,
                              controller_vectors);
    vtu_writer->load(state);
    mesh_transfer.load(state);
    if (state.count("refinement_pending") &&
        state.at("refinement_pending") == "1")
      // the run ended on a step after which the mesh adapts: adapt now, as
      // the uninterrupted run did (the active sets refer to the old mesh)
      refine_mesh();
    else
      {
        make_integrator();
        integrator->load_active_sets(flags);
      }
    if (time_step_controller.is_adaptive() &&
        state.count("step_matrices_built"))
      // those of the run before the checkpoint; make_integrator() above
      // built one more, which counts
      n_step_matrices = std::stoul(state.at("step_matrices_built"));
    open_outputs();
    pcout << "   resumed from " << dir << " at step " << control.get_step()
          << ", t = " << control.get_time() << " s" << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::record_statistics()
  {
    postprocessors->execute(*timer);
    TimerOutput::Scope t(*timer, "diagnostics");
    postprocessors->check_last_row();
    reference_states->write(control.get_time());
    mesh_transfer = MeshTransfer();
  }



  template <int dim>
  void
  Simulator<dim>::refine_mesh()
  {
    const double energy_before = system->total_energy(u, udot);
    {
      TimerOutput::Scope t(*timer, "mesh adaptation");
      mesh_adaptor->mark_cells(triangulation);
      // transfer u and udot to the new mesh (p4est repartitions it)
      triangulation.prepare_coarsening_and_refinement();
      system->prepare_for_refinement(u, udot);
      triangulation.execute_coarsening_and_refinement();
    }
    setup_discretization();
    {
      TimerOutput::Scope t(*timer, "mesh adaptation");
      system->interpolate_after_refinement(u, udot);
    }
    // the estimates and the rows' states refer to the old mesh
    time_step_controller.reset(contact->get_rows().size());
    make_integrator();

    // the transferred displacement may violate the new K_h: back onto it
    double violation;
    {
      TimerOutput::Scope t(*timer, "mesh adaptation");
      violation =
        integrator->restore_constraints(u, contact->get_row_operator());
    }
    mesh_transfer.add(system->total_energy(u, udot) - energy_before, violation);
  }



  template <int dim>
  std::string
  Simulator<dim>::write_checkpoint()
  {
    TimerOutput::Scope t(*timer, "checkpoint");
    const std::string  dir = checkpoints.begin(control.get_step());
    std::map<std::string, std::string> state;
    VectorType                         flags(u);
    integrator->save_active_sets(flags);
    const std::vector<VectorType> controller_vectors =
      time_step_controller.save(state, contact->get_rows(), flags, u);
    std::vector<const VectorType *> vectors = {&u, &udot, &flags};
    for (const VectorType &v : controller_vectors)
      vectors.push_back(&v);
    system->prepare_for_serialization(vectors);
    triangulation.save(Checkpoints::mesh_file(dir));
    control.save(state);
    postprocessors->save(state);
    mesh_transfer.save(state);
    vtu_writer->save(state);
    // the last step of a run does not adapt the mesh: a resumed run does
    state["refinement_pending"] =
      moments.last && mesh_adaptor->refinement_due(control.get_step()) ? "1" :
                                                                         "0";
    state["step_matrices_built"] = std::to_string(
      n_step_matrices + integrator->get_operators().n_step_matrices_built);
    checkpoints.finish(dir, state);
    return dir;
  }



  template <int dim>
  void
  Simulator<dim>::stop_after_failed_step(const bool finite)
  {
    std::ostringstream message;
    if (control.get_step() == 0 && !checkpoints.resume())
      {
        // nothing to keep: the output directory stays as it was
        message << std::setprecision(6) << "the first step (tau = "
                << time_step_controller.get_timestep() << " s) failed: "
                << (finite && !report.converged() ?
                      report.failure() :
                      "the solution is not finite")
                << ". Nothing was written. Try a smaller Time integration/Time "
                   "step, or set 'Time integration/Time step adaptation = "
                   "true'.";
        AssertThrow(false, ExcMessage(message.str()));
      }
    const std::string dir = write_checkpoint();
    message << std::setprecision(6) << "step " << control.get_step() + 1
            << " (from t = " << control.get_time()
            << " s, tau = " << time_step_controller.get_timestep()
            << " s) failed: "
            << (finite && !report.converged() ? report.failure() :
                                                "the solution is not finite")
            << ". The last good state (step " << control.get_step()
            << ") is the checkpoint '" << dir
            << "' (resume with 'Checkpointing/Resume = true'), or set 'Time "
               "integration/Time step adaptation = true'.";
    AssertThrow(false, ExcMessage(message.str()));
    std::abort();
  }



  template <int dim>
  TimeStepController::AcceptedStep
  Simulator<dim>::take_step()
  {
    copy_with_layout(u_old, u);
    copy_with_layout(udot_old, udot);
    // where the step starts from: its active sets
    const auto start_sets = integrator->active_sets();
    time_step_controller.begin_step(control.get_time());
    while (true)
      {
        const double tau = time_step_controller.trial_timestep();
        {
          TimerOutput::Scope t(*timer, "time step");
          report = integrator->step(tau,
                                    !time_step_controller.step_is_shortened(),
                                    u,
                                    udot);
        }
        check_inertia();
        const bool finite =
          std::isfinite(u.l2_norm()) && std::isfinite(udot.l2_norm());
        if (!report.converged() || !finite)
          {
            // back to the last good state, warm started from the failed
            // trial's active sets: retry with a smaller step, or stop
            const auto active = integrator->active_sets();
            u                 = u_old;
            udot              = udot_old;
            if (!time_step_controller.retry_after_failure())
              stop_after_failed_step(finite);
            pcout << "   warning: step " << control.get_step() + 1
                  << " (t = " << control.get_time()
                  << " s) failed; retrying with tau = "
                  << time_step_controller.get_timestep() << " s" << std::endl;
            integrator->warm_start(active.first, active.second);
            continue;
          }
        if (time_step_controller.is_adaptive())
          {
            TimerOutput::Scope t(*timer, "time step control");
            if (time_step_controller.judge(integrator->get_operators(),
                                           contact->get_row_operator(),
                                           start_sets.first,
                                           u_old,
                                           udot_old,
                                           u,
                                           udot,
                                           report,
                                           comm) ==
                TimeStepController::Verdict::retry)
              {
                // from the start of the step, with its active sets
                u    = u_old;
                udot = udot_old;
                integrator->warm_start(start_sets.first, start_sets.second);
                continue;
              }
          }
        return time_step_controller.accept();
      }
  }



  template <int dim>
  void
  Simulator<dim>::run_time_loop()
  {
    pcout << "dyncontact: scene '" << scene->name() << "', " << dim
          << "D, scheme " << scheme.name << ", "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
          << std::endl;
    // the output directory must be writable; nothing in it is touched
    // before the setup has succeeded
    output_directory =
      std::make_unique<OutputDirectory>(parameters.output_directory, comm);
    build_mesh();
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
        const auto step = take_step();
        moments         = control.advance(step.tau, step.tau_changed);
        moments.refinement =
          mesh_adaptor->refinement_due(control.get_step()) && !moments.last;
        step_timer.stop();
        step_wall_time = step_timer.wall_time();
        record_statistics();
        if (!outputs_open)
          open_outputs();
        progress->step(
          control.get_step(),
          control.get_time(),
          control.get_end_time(),
          report.tau,
          Utilities::MPI::sum<types::global_dof_index>(
            std::count(report.active.begin(), report.active.end(), 1), comm),
          contact->n_global_rows(),
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
    run_report.write_summary(
      run_clock.wall_time(),
      loop_clock.wall_time(),
      n_step_matrices + integrator->get_operators().n_step_matrices_built);
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
    catch (...)
      {
        // TimerOutput would otherwise print an MPI warning while the
        // exception unwinds; the user gets the exception's message instead
        timer.reset();
        throw;
      }
    return postprocessors->get_statistics();
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace dyncontact
