#include <deal.II/base/mpi.h>

#include <dyncontact/base/memory_check.h>
#include <dyncontact/base/triangulation.h>
#include <dyncontact/base/vector_copy.h>
#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/discretization/body_sums.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/problem/discrete_problem.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/step_multigrid.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace dyncontact
{
  template <int dim>
  DiscreteProblem<dim>::DiscreteProblem(const Scheme             &scheme,
                                        const Parameters         &parameters,
                                        const ConditionalOStream &pcout,
                                        const MPI_Comm            comm)
    : triangulation(
        make_triangulation<dim>(parameters.serial_triangulation, comm))
    , comm(comm)
    , pcout(pcout)
    , scheme(scheme)
    , parameters(parameters)
  {
    AssertThrow(!parameters.serial_triangulation ||
                  Utilities::MPI::n_mpi_processes(comm) == 1,
                ExcMessage(
                  "Mesh/Triangulation = serial holds the whole mesh "
                  "in deal.II's Triangulation on one MPI rank, but "
                  "this run has " +
                  std::to_string(Utilities::MPI::n_mpi_processes(comm)) +
                  " ranks: run it on one rank, or set "
                  "'Triangulation' to distributed (a run resumed from "
                  "a checkpoint keeps the triangulation it was written "
                  "with: resume a serial one on one rank)."));
  }



  template <int dim>
  void
  DiscreteProblem<dim>::parse_parameters(ParameterHandler &prm)
  {
    solver_parameters.parse_parameters(prm);
    AssertThrow(!(scheme.is_static && parameters.numerical_dissipation > 0.),
                ExcMessage("Time integration/Numerical dissipation > 0 is "
                           "for the dynamic schemes; the static problem "
                           "(Time integration/Scheme = " +
                           scheme.name +
                           ") has no time steps to dissipate in: set it to "
                           "0."));
    AssertThrow(!(scheme.is_static && solver_parameters.matrix_free_step),
                ExcMessage("Contact solver/Step matrix = matrix-free is for "
                           "the dynamic schemes (its Jacobi preconditioner "
                           "needs the mass in S); the static problem "
                           "(Time integration/Scheme = " +
                           scheme.name +
                           ") solves with the stiffness alone and AMG: set "
                           "'Step matrix' to assembled."));
    auto discretization = parameters.system;
    discretization.assembled_step_matrix =
      scheme.is_static || !solver_parameters.matrix_free_step;
    system =
      std::make_unique<SemiDiscreteSystem<dim>>(discretization, mapping, comm);
    if (solver_parameters.preconditioner ==
        ActiveSetSolver::Parameters::Preconditioner::multigrid)
      {
        AssertThrow(parameters.system.degree >= 2,
                    ExcMessage(
                      "Contact solver/Preconditioner = multigrid coarsens "
                      "the Polynomial degree to 1, but the degree is "
                      "already 1: for linear elements set 'Step matrix' to "
                      "assembled and 'Preconditioner' to AMG or "
                      "automatic."));
        auto linear                  = discretization;
        linear.degree                = 1;
        linear.assembled_step_matrix = true;
        linear.multigrid_level       = true;
        coarse_system =
          std::make_unique<SemiDiscreteSystem<dim>>(linear, mapping, comm);
        multigrid = std::make_unique<StepMultigrid<dim>>(
          *system,
          *coarse_system,
          solver_parameters.amg_rotations,
          solver_parameters.amg_smoothed_prolongator,
          comm);
      }
    typename ContactSetup<dim>::Parameters contact_parameters;
    contact_parameters.parse_parameters(prm);
    contact = std::make_unique<ContactSetup<dim>>(contact_parameters, comm);
  }



  template <int dim>
  DiscreteProblem<dim>::~DiscreteProblem() = default;



  template <int dim>
  void
  DiscreteProblem<dim>::build_mesh(const Scene<dim>  &scene,
                                   const unsigned int n_refinements,
                                   const bool         coarse_only,
                                   TimerOutput       &timer)
  {
    TimerOutput::Scope t(timer, "setup: mesh");
    dyncontact::build_mesh(scene,
                           *triangulation,
                           n_refinements,
                           system->get_fe().degree,
                           coarse_only);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::setup(const Scene<dim> &scene,
                              TimerOutput      &timer,
                              const bool        adapting)
  {
    const std::string prefix = adapting ? "adaptation: " : "";
    {
      TimerOutput::Scope t(timer,
                           adapting ? "adaptation: DoFs and sparsity" :
                                      "setup: DoFs and sparsity");
      system->setup(*triangulation, scene);
      if (coarse_system)
        coarse_system->setup(*triangulation, scene);
      // the dynamic sparsity pattern's rows; without a pattern nothing
      // large was freed (and the trim costs 7 % of a small adaptation)
      if (matrices_assembled())
        release_freed_memory();
      pcout << "   cells: " << triangulation->n_global_active_cells()
            << ", DoFs: " << system->get_dof_handler().n_dofs() << std::endl;
    }
    {
      TimerOutput::Scope t(timer, prefix + "assembly");
      system->assemble(scene);
      if (coarse_system)
        {
          coarse_system->assemble(scene);
          multigrid->reinit();
        }
      if (scheme.is_static)
        check_rigid_motions(scene);
    }
    TimerOutput::Scope t(timer, prefix + "contact rows");
    contact->setup(scene, *system, mapping, pcout);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::make_integrator(const double tau,
                                        TimerOutput &timer,
                                        const bool   adapting)
  {
    TimerOutput::Scope t(timer,
                         adapting ?
                           "adaptation: step matrix and preconditioner" :
                           "setup: step matrix and preconditioner");
    if (integrator)
      n_earlier_step_matrices +=
        integrator->get_operators().n_step_matrices_built;
    ActiveSetSolver::NearNullSpace near_null_space;
    near_null_space.translations = system->get_constant_modes();
    if (solver_parameters.amg_rotations)
      near_null_space.rotations = system->rotation_modes();
    SystemMatrices matrices = system->matrices();
    if (multigrid)
      matrices.step_preconditioner = [this](const double      a,
                                            const double      b,
                                            const Product    &S_vmult,
                                            const VectorType &S_diagonal) {
        return multigrid->make_preconditioner(a, b, S_vmult, S_diagonal);
      };
    std::function<void(double)> move_obstacles;
    if (contact->get_rows().obstacles_move())
      move_obstacles = [this](const double t) {
        contact->set_obstacle_time(t);
      };
    integrator = std::make_unique<TimeIntegrator>(
      scheme,
      parameters.numerical_dissipation,
      tau,
      StepOperatorInputs{matrices,
                         solver_parameters,
                         system->locally_owned_dofs(),
                         system->locally_relevant_dofs(),
                         system->get_constraints(),
                         contact->get_rows(),
                         near_null_space,
                         comm,
                         move_obstacles});
    // ML's temporaries (AMG is made only on an assembled matrix)
    if (matrices_assembled())
      release_freed_memory();
    check_inertia();
  }



  template <int dim>
  void
  DiscreteProblem<dim>::check_inertia()
  {
    if (warned_inertia)
      return;
    const std::string warning = integrator->inertia_warning();
    warned_inertia            = !warning.empty();
    pcout << warning;
  }



  template <int dim>
  std::array<double, 2>
  DiscreteProblem<dim>::interpolate_initial_values(const Scene<dim> &scene)
  {
    return system->interpolate_initial_values(scene, u, udot);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::start(const Scene<dim> &scene,
                              const double      tau,
                              TimerOutput      &timer)
  {
    const auto reset = interpolate_initial_values(scene);
    for (unsigned int k = 0; k < 2; ++k)
      if (reset[k] > 0.)
        pcout << "   warning: the initial "
              << (k == 0 ? "displacement" : "velocity") << " is up to "
              << reset[k] << (k == 0 ? " m" : " m/s")
              << " at nodes that Dirichlet boundaries hold at zero: those "
                 "nodes start at zero (and the initial energy lacks their "
                 "share)."
              << std::endl;
    // Dirichlet data that move: u = g(0) and udot = dg/dt(0) on their nodes
    system->set_prescribed_state(0., 1e-3 * tau, u, &udot);
    make_integrator(tau, timer);
    project_initial_penetration();
    contact->refuse_initial_overlap(u);
    {
      TimerOutput::Scope t(timer, "time step");
      report = integrator->initialize(tau, u, udot);
    }
    AssertThrow(report.converged(),
                ExcMessage("The initial velocity of " + scheme.name +
                           " (eq. 12c) could not be computed: " +
                           failure_cause(tau, report.failure()) + "."));
    initial_report = report;
  }



  template <int dim>
  VectorType
  DiscreteProblem<dim>::active_set_flags() const
  {
    VectorType flags(u);
    integrator->save_active_sets(flags);
    return flags;
  }



  template <int dim>
  void
  DiscreteProblem<dim>::save(const std::string             &mesh_file,
                             const VectorType              &flags,
                             const std::vector<VectorType> &more)
  {
    std::vector<const VectorType *> vectors = {&u, &udot, &flags};
    for (const VectorType &v : more)
      vectors.push_back(&v);
    system->save(mesh_file, vectors);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::load_mesh(const std::string &mesh_file)
  {
    SemiDiscreteSystem<dim>::load_mesh(mesh_file, *triangulation);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::load(const std::string       &mesh_file,
                             VectorType              &flags,
                             std::vector<VectorType> &more)
  {
    std::vector<VectorType *> vectors = {&u, &udot, &flags};
    for (VectorType &v : more)
      vectors.push_back(&v);
    system->load_vectors(mesh_file, vectors);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::restore_reported_active_sets(const VectorType &flags)
  {
    std::tie(report.active, report.projection_active) =
      TimeIntegrator::decode_active_sets(contact->get_rows(), flags);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::resume_integrator(const double      tau,
                                          const VectorType &flags,
                                          TimerOutput      &timer)
  {
    if (integrator)
      return;
    make_integrator(tau, timer);
    integrator->load_active_sets(flags);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::project_initial_penetration()
  {
    double largest = 0.;
    for (const double v : contact->get_row_operator().constraint_values(u))
      largest = std::max(largest, v);
    largest = Utilities::MPI::max(largest, comm);
    // (the reference configuration was checked when the rows were set up:
    // here the initial displacement makes it penetrate)
    AssertThrow(largest <= 1e-12 || contact->projects_initial_penetration(),
                ExcMessage("The initial displacement makes the bodies "
                           "penetrate (a slave node inside the obstacle or "
                           "its master body) by up to " +
                           Utilities::to_string(largest) +
                           " m. Correct it, or set 'Contact/Initial "
                           "penetration = project'."));
    if (largest > 1e-12)
      {
        integrator->project_onto_constraints(u);
        pcout << "   warning: the initial configuration penetrated by up to "
              << largest << " m; the initial displacement was projected onto "
              << "K_h." << std::endl;
      }
  }



  template <int dim>
  void
  DiscreteProblem<dim>::begin_step()
  {
    copy_with_layout(u_old, u);
    copy_with_layout(udot_old, udot);
    start_sets   = integrator->active_sets();
    load_stepped = false;
  }



  template <int dim>
  void
  DiscreteProblem<dim>::set_load_time(const double t)
  {
    system->set_load_time(t);
    contact->set_obstacle_time(t);
  }



  template <int dim>
  const StepReport &
  DiscreteProblem<dim>::try_step(const double tau,
                                 const double t_end,
                                 const bool   level_step,
                                 TimerOutput &timer)
  {
    if (system->loads_change_in_time())
      {
        TimerOutput::Scope t(timer, "loads that change in time");
        system->begin_step_load(t_end);
      }
    {
      TimerOutput::Scope t(timer, "time step");
      step_start_time = t_end - tau;
      integrator->set_step_times(step_start_time, t_end);
      report = integrator->step(tau, level_step, u, udot);
    }
    system->end_step_load();
    load_stepped = true;
    check_inertia();
    return report;
  }



  template <int dim>
  bool
  DiscreteProblem<dim>::trial_is_finite() const
  {
    return std::isfinite(u.l2_norm()) && std::isfinite(udot.l2_norm());
  }



  template <int dim>
  void
  DiscreteProblem<dim>::restore(const bool from_trial)
  {
    const auto active = from_trial ? integrator->active_sets() : start_sets;
    u                 = u_old;
    udot              = udot_old;
    if (load_stepped)
      system->undo_step_load();
    // (rigid obstacles that move: back where they were at t_n)
    contact->set_obstacle_time(step_start_time);
    load_stepped = false;
    integrator->warm_start(active.first, active.second);
  }



  template <int dim>
  TrialStep
  DiscreteProblem<dim>::trial()
  {
    return {integrator->get_operators(),
            contact->get_row_operator(),
            start_sets.first,
            u_old,
            udot_old,
            u,
            udot,
            report};
  }



  template <int dim>
  typename DiscreteProblem<dim>::Adaptation
  DiscreteProblem<dim>::adapt_mesh(const Scene<dim>            &scene,
                                   const std::function<void()> &mark_cells,
                                   const std::string           &remedy,
                                   const double                 tau,
                                   TimerOutput                 &timer,
                                   const bool                   keep_motion)
  {
    {
      TimerOutput::Scope t(timer, "adaptation: indicators and flags");
      mark_cells();
      // a mesh that does not change keeps its DoFs, operators and rows
      const auto flagged = [&]() {
        bool any = false;
        for (const auto &cell : triangulation->active_cell_iterators())
          if (cell->is_locally_owned() &&
              (cell->refine_flag_set() || cell->coarsen_flag_set()))
            {
              any = true;
              break;
            }
        return Utilities::MPI::logical_or(any, comm);
      };
      // no flag on any rank: the smoothing of the flags (a pass over all
      // cells, repeated until nothing changes, and collective for p4est)
      // has nothing to add to a mesh that came out of a refinement (with
      // the smoothings of make_triangulation()), and is skipped
      if (!flagged())
        return {};
      triangulation->prepare_coarsening_and_refinement();
      // (the memory for the mesh it would make, before it is made)
      if (!check_flagged_mesh_fits_in_memory(scene, remedy))
        return {};
    }
    // (only where the mesh changes: an adaptation that marks no cell
    // costs no energy evaluation; the energy before reads A u from the
    // last step's cache, the one after computes A u on the new mesh, which
    // the next step then finds in the cache); with each body's momentum and
    // mean displacement, and before the transfer its mean velocity where
    // the transfer keeps it
    struct Measures
    {
      double              energy;
      std::vector<double> momenta;
      /// the mean displacements, and the mean velocities if asked for
      std::vector<std::vector<double>> means;
    };
    const auto measure = [&](const bool with_velocities) {
      TimerOutput::Scope              t(timer, "adaptation: energy transfer");
      const unsigned int              n_bodies = scene.n_bodies();
      std::vector<const VectorType *> xs       = {&u};
      if (with_velocities)
        xs.push_back(&udot);
      return Measures{system->total_energy(u, udot),
                      body_sums(*system, udot, n_bodies, comm),
                      body_means(*system, xs, n_bodies, comm)};
    };
    const Measures before = measure(keep_motion);
    {
      TimerOutput::Scope t(timer, "adaptation: refinement and transfer");
      // transfer u and udot to the new mesh (p4est also repartitions it)
      system->prepare_for_refinement(u, udot);
      triangulation->execute_coarsening_and_refinement();
    }
    setup(scene, timer, true);
    {
      TimerOutput::Scope t(timer, "adaptation: refinement and transfer");
      system->interpolate_after_refinement(u, udot);
      // (Dirichlet data that move: their values on the new mesh's nodes)
      system->set_prescribed_state(system->get_load_time(),
                                   1e-3 * tau,
                                   u,
                                   &udot);
      // (the rigid translation that undoes the transfer's shift of each
      // free body's centre of mass and of its velocity)
      if (keep_motion)
        shift_body_means(
          *system, {&u, &udot}, before.means, scene.n_bodies(), comm);
    }
    make_integrator(tau, timer, true);

    // the transferred displacement may penetrate the new K_h: back onto it
    Adaptation adaptation;
    adaptation.changed = true;
    {
      TimerOutput::Scope t(timer, "adaptation: constraints restored");
      adaptation.penetration =
        integrator->restore_constraints(u, contact->get_row_operator());
    }
    const Measures after     = measure(false);
    adaptation.energy_change = after.energy - before.energy;
    adaptation.momentum_change =
      largest_body_change(before.momenta, after.momenta);
    adaptation.displacement_change =
      largest_body_change(before.means[0], after.means[0]);
    return adaptation;
  }



  template <int dim>
  void
  DiscreteProblem<dim>::swap_with_initial_state()
  {
    std::swap(u, u_old);
    std::swap(udot, udot_old);
    std::swap(report, initial_report);
  }



  template <int dim>
  unsigned int
  DiscreteProblem<dim>::n_step_matrices() const
  {
    return n_earlier_step_matrices +
           (integrator ? integrator->get_operators().n_step_matrices_built : 0);
  }



  template <int dim>
  void
  DiscreteProblem<dim>::set_n_earlier_step_matrices(const unsigned int n)
  {
    n_earlier_step_matrices = n;
  }

  template class DiscreteProblem<2>;
  template class DiscreteProblem<3>;
} // namespace dyncontact
