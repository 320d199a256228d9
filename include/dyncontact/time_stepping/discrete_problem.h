#ifndef dyncontact_time_stepping_discrete_problem_h
#define dyncontact_time_stepping_discrete_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/contact/active_set_solver.h>
#include <dyncontact/time_stepping/integrators.h>
#include <dyncontact/time_stepping/time_step_controller.h>

#include <functional>
#include <memory>
#include <utility>

namespace dyncontact
{
  template <int dim>
  class Scene;
  template <int dim>
  class SemiDiscreteSystem;
  template <int dim>
  class ContactSetup;
  template <int dim>
  class StepMultigrid;

  /**
   * What a step solves, on the current mesh: the triangulation, its
   * semi-discrete system (DoFs, constraints, M, A, B, f), the contact rows,
   * the scheme's integrator, and the state: (u, udot), and (u_old,
   * udot_old) where the present step started from. The Simulator sets it
   * up, steps it and adapts its mesh; statistics read it through
   * SimulatorAccess. tau is the TimeStepController's.
   */
  template <int dim>
  class DiscreteProblem
  {
  public:
    /// Reads the parameters of the contact rows and the active-set solver
    /// from @p prm; @p numerical_dissipation: theta of the integrator
    /// (Time integration/Numerical dissipation); @p system_parameters: the
    /// polynomial degree and the mass matrix; @p serial_triangulation:
    /// deal.II's Triangulation instead of p4est's (Mesh/Triangulation =
    /// serial, one rank only).
    DiscreteProblem(
      ParameterHandler                                   &prm,
      const Scheme                                       &scheme,
      const double                                        numerical_dissipation,
      const typename SemiDiscreteSystem<dim>::Parameters &system_parameters,
      TimeStepController                                 &time_step_controller,
      const ConditionalOStream                           &pcout,
      const MPI_Comm                                      comm,
      const bool serial_triangulation = false);

    ~DiscreteProblem();

    /// The scene's coarse mesh, refined @p n_refinements times unless
    /// @p coarse_only (a resumed run loads its mesh onto the coarse one).
    void
    build_mesh(const Scene<dim>  &scene,
               const unsigned int n_refinements,
               const bool         coarse_only,
               TimerOutput       &timer);

    /// DoFs, matrices and contact rows on the current mesh, timed as
    /// 'setup: DoFs and sparsity', 'assembly' and 'contact rows', or, in a
    /// mesh adaptation (@p adapting), as 'adaptation: DoFs and sparsity',
    /// 'adaptation: assembly' and 'adaptation: contact rows'.
    void
    setup(const Scene<dim> &scene,
          TimerOutput      &timer,
          const bool        adapting = false);

    /// The step matrix, its preconditioner and the active-set solvers for
    /// the controller's tau, timed as 'setup: step matrix and
    /// preconditioner', or 'adaptation: step matrix and preconditioner'.
    void
    make_integrator(TimerOutput &timer, const bool adapting = false);

    /// An initially penetrating u (allowed only with 'Initial penetration
    /// = project'): its M-projection onto K_h, with a warning.
    void
    project_initial_penetration();

    /// What take_step() did.
    struct Outcome
    {
      TimeStepController::AcceptedStep step;
      bool                             failed = false;
      /// of a failed trial: whether its solution was finite
      bool finite = true;
    };
    /// One step from (u, udot) = (u_old, udot_old) at time @p time (step
    /// @p step): trial steps with the TimeStepController's tau until it
    /// accepts one (it retries after a failed solve, a located contact
    /// event, an error estimate above the tolerance). A failed trial that
    /// cannot be retried leaves the state as it was and reports failed.
    Outcome
    take_step(const double time, const unsigned int step, TimerOutput &timer);

    /// Refines and coarsens the cells @p mark_cells marks, transfers (u,
    /// udot) and sets up everything anew; returns the energy change of the
    /// transfer and the largest violation of the new K_h that was projected
    /// away. If no cell is marked (on any rank), nothing changes and both
    /// are zero. A refinement whose growth would not fit into the memory
    /// available is refused with a message naming @p remedy (the
    /// parameters to reduce) before the mesh changes.
    std::pair<double, double>
    adapt_mesh(const Scene<dim>            &scene,
               const std::function<void()> &mark_cells,
               const std::string           &remedy,
               TimerOutput                 &timer);

    /// Stops with a message naming @p what (the mesh) and @p remedy if the
    /// cells flagged now
    /// (refined: 2^dim children each; coarsened: 2^dim siblings become one)
    /// would grow the mesh beyond the memory available to the run
    /// (check_mesh_fits_in_memory()); returns whether any cell is flagged.
    /// Collective.
    bool
    check_flagged_mesh_fits_in_memory(
      const Scene<dim>  &scene,
      const std::string &remedy,
      const std::string &what = "the adapted mesh") const;

    /// The cause of a failed solve for its message: @p failure (the
    /// solver's word), after a sentence that says so if the velocity udot
    /// moves a point farther in a step of @p tau than the whole mesh is
    /// wide (the cause is then the data's scale, not a solver limit).
    /// Collective.
    std::string
    failure_cause(const double tau, const std::string &failure) const;

    /// Swaps (u, udot, report) with (u_old, udot_old, initial_report):
    /// after the first step, the initial state (and back).
    void
    swap_with_initial_state();

    /// Step matrices S built so far, by all integrators.
    unsigned int
    n_step_matrices() const;

    /// A resumed run: the step matrices the run before the checkpoint
    /// built (the present integrator's count on top).
    void
    set_n_earlier_step_matrices(const unsigned int n);

  private:
    std::unique_ptr<Triangulation<dim>> triangulation_storage;

  public:
    /// p4est's parallel::distributed::Triangulation, or with
    /// Mesh/Triangulation = serial deal.II's Triangulation (one rank).
    Triangulation<dim>  &triangulation;
    const MappingQ1<dim> mapping;

    const SemiDiscreteSystem<dim> &
    get_system() const
    {
      return *system;
    }
    SemiDiscreteSystem<dim> &
    get_system()
    {
      return *system;
    }
    const ContactSetup<dim> &
    get_contact() const
    {
      return *contact;
    }
    ContactSetup<dim> &
    get_contact()
    {
      return *contact;
    }
    /// Whether make_integrator() has run (a resumed run's adaptation of an
    /// unchanged mesh makes none).
    bool
    has_integrator() const
    {
      return integrator != nullptr;
    }
    const TimeIntegrator &
    get_integrator() const
    {
      return *integrator;
    }
    TimeIntegrator &
    get_integrator()
    {
      return *integrator;
    }

    VectorType u, udot, u_old, udot_old;
    /// the last trial step's, and the initial velocity's (eq. 12c)
    StepReport report, initial_report;

  private:
    /// The static scheme: stops with a message naming each body that
    /// neither a Dirichlet boundary nor its load holds
    /// (unheld_rigid_motions()).
    void
    check_rigid_motions(const Scene<dim> &scene) const;

    /// Warns once if S = M + tau^2/4 A + tau/2 B keeps the mass only to a
    /// poor relative accuracy.
    void
    check_inertia();

    /// Whether any matrix is assembled on the current mesh (a sparsity
    /// pattern of the system's, or the multigrid's linear level): only
    /// then do the set-ups free enough memory in small blocks to be worth
    /// release_freed_memory().
    bool
    matrices_assembled() const
    {
      return system->has_sparsity_pattern() || coarse_system;
    }

    const MPI_Comm            comm;
    const ConditionalOStream &pcout;
    const Scheme             &scheme;
    /// Time integration/Numerical dissipation theta, for the integrator.
    const double                             numerical_dissipation;
    TimeStepController                      &time_step_controller;
    ActiveSetSolver::Parameters              solver_parameters;
    std::unique_ptr<SemiDiscreteSystem<dim>> system;
    /// 'Contact solver/Preconditioner = multigrid': the same mesh with
    /// linear elements, and the p-multigrid between the two
    std::unique_ptr<SemiDiscreteSystem<dim>> coarse_system;
    std::unique_ptr<StepMultigrid<dim>>      multigrid;
    std::unique_ptr<ContactSetup<dim>>       contact;
    std::unique_ptr<TimeIntegrator>          integrator;
    bool                                     warned_inertia = false;
    /// built by the integrators of earlier meshes
    unsigned int n_earlier_step_matrices = 0;
  };
} // namespace dyncontact

#endif
