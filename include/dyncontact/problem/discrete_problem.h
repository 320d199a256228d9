#ifndef dyncontact_problem_discrete_problem_h
#define dyncontact_problem_discrete_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/contact/active_set_solver.h>
#include <dyncontact/time_stepping/integrators.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <array>
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
   * udot_old) where the present step started from. The state is its own:
   * the Simulator starts it (or loads it from a checkpoint),
   * SimulationControl asks it for the trial steps of each step
   * (SteppedProblem) and hands it tau, MeshAdaptor adapts its mesh, and
   * statistics read it through SimulatorAccess.
   */
  template <int dim>
  class DiscreteProblem : public SteppedProblem
  {
  public:
    /// What it is handed by the owners of the entries.
    struct Parameters
    {
      /// Polynomial degree and Time integration/Mass matrix.
      typename SemiDiscreteSystem<dim>::Parameters system;
      /// Time integration/Numerical dissipation theta, for the integrator.
      double numerical_dissipation = 0.;
      /// Mesh/Triangulation = serial: deal.II's Triangulation instead of
      /// p4est's (one rank only).
      bool serial_triangulation = false;
    };

    /// The triangulation; the rest is made by parse_parameters().
    DiscreteProblem(const Scheme             &scheme,
                    const Parameters         &parameters,
                    const ConditionalOStream &pcout,
                    const MPI_Comm            comm);

    /// Reads the subsections it owns, Contact solver (the active-set
    /// solver) and Contact (the contact rows), and makes the system (and
    /// the multigrid's linear level).
    void
    parse_parameters(ParameterHandler &prm);

    /// Whether the step matrix is assembled and stored (Contact
    /// solver/Step matrix = assembled).
    bool
    assembles_step_matrix() const
    {
      return !solver_parameters.matrix_free_step;
    }

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
    /// @p tau, timed as 'setup: step matrix and preconditioner', or
    /// 'adaptation: step matrix and preconditioner'.
    void
    make_integrator(const double tau,
                    TimerOutput &timer,
                    const bool   adapting = false);

    /// (u, udot) of the scene's initial values (on the present mesh); the
    /// largest values the Dirichlet constraints reset to zero (see
    /// SemiDiscreteSystem::interpolate_initial_values()).
    std::array<double, 2>
    interpolate_initial_values(const Scene<dim> &scene);

    /// The initial state of a new run: the scene's initial values, the
    /// integrator for @p tau, an initially penetrating u (allowed only with
    /// 'Initial penetration = project') projected onto K_h with a warning,
    /// an overlap of unpaired bodies refused, and the scheme's initial
    /// velocity (eq. 12c), timed as 'time step'; stops with a message if it
    /// cannot be computed.
    void
    start(const Scene<dim> &scene, const double tau, TimerOutput &timer);

    /// @name Checkpoints
    /// @{

    /// The integrator's active sets as a nodal vector laid out as u
    /// (TimeIntegrator::save_active_sets()).
    VectorType
    active_set_flags() const;

    /// Writes the mesh and (u, udot, @p flags, @p more) to @p mesh_file.
    void
    save(const std::string             &mesh_file,
         const VectorType              &flags,
         const std::vector<VectorType> &more);

    /// Loads the mesh of @p mesh_file onto the coarse mesh (before
    /// setup()).
    void
    load_mesh(const std::string &mesh_file);

    /// Reads (u, udot, @p flags, @p more) of @p mesh_file on the set-up
    /// mesh (as many vectors as @p more has).
    void
    load(const std::string       &mesh_file,
         VectorType              &flags,
         std::vector<VectorType> &more);

    /// The last step's active sets in the report (get_report(): what a
    /// mesh adaptation reads of the last step) from the @p flags of a
    /// checkpoint, for the adaptation that a resume runs before any step.
    void
    restore_reported_active_sets(const VectorType &flags);

    /// The integrator for @p tau with the active sets of @p flags, unless
    /// one was made since (by a mesh adaptation after loading).
    /// After a resume at time @p t: the loads at @p t.
    void
    set_load_time(const double t);
    void
    resume_integrator(const double      tau,
                      const VectorType &flags,
                      TimerOutput      &timer);
    /// @}

    /// @name The trial steps SimulationControl::advance() asks for
    /// @{
    void
    begin_step() override;
    const StepReport &
    try_step(const double tau,
             const double t_end,
             const bool   level_step,
             TimerOutput &timer) override;
    bool
    trial_is_finite() const override;
    void
    restore(const bool from_trial) override;
    TrialStep
    trial() override;
    /// @}

    /// What adapt_mesh() did.
    struct Adaptation
    {
      /// whether any cell was refined or coarsened (else nothing changed)
      bool changed = false;
      /// the energy change of the transfer (J)
      double energy_change = 0.;
      /// the largest penetration of the new K_h that the transfer left and
      /// that was projected away (m)
      double penetration = 0.;
      /// the largest change of a body's momentum (as the momentum columns)
      /// and of its mean displacement (m), the projection included
      double momentum_change = 0., displacement_change = 0.;
    };

    /// Refines and coarsens the cells @p mark_cells marks, transfers (u,
    /// udot), sets up everything anew with the step @p tau and projects u
    /// back onto the new K_h. If no cell is marked (on any rank), nothing
    /// changes. A refinement whose growth would not fit into the memory
    /// available is refused with a message naming @p remedy (the
    /// parameters to reduce) before the mesh changes. With @p keep_motion
    /// the transfer keeps each body's centre of mass and its velocity where
    /// no Dirichlet data hold the body's component (shift_body_means()).
    Adaptation
    adapt_mesh(const Scene<dim>            &scene,
               const std::function<void()> &mark_cells,
               const std::string           &remedy,
               const double                 tau,
               TimerOutput                 &timer,
               const bool                   keep_motion = false);

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

    /// @name The read-only view (SimulatorAccess)
    /// @{

    /// u^n and udot^n after the last step.
    const VectorType &
    get_solution() const
    {
      return u;
    }
    const VectorType &
    get_velocity() const
    {
      return udot;
    }
    /// u^{n-1}: the displacement before the last step.
    const VectorType &
    get_old_solution() const
    {
      return u_old;
    }
    /// What the last trial step (or the initial velocity, at step 0)
    /// reported.
    const StepReport &
    get_report() const
    {
      return report;
    }
    /// @}

    /// Step matrices S built so far, by all integrators.
    unsigned int
    n_step_matrices() const;

    /// A resumed run: the step matrices the run before the checkpoint
    /// built (the present integrator's count on top).
    void
    set_n_earlier_step_matrices(const unsigned int n);

    /// p4est's parallel::distributed::Triangulation, or with
    /// Mesh/Triangulation = serial deal.II's Triangulation (one rank).
    const Triangulation<dim> &
    get_triangulation() const
    {
      return *triangulation;
    }
    /// For the refinement flags of a mesh adaptation (MeshAdaptor).
    Triangulation<dim> &
    get_triangulation()
    {
      return *triangulation;
    }
    const Mapping<dim> &
    get_mapping() const
    {
      return mapping;
    }

    const SemiDiscreteSystem<dim> &
    get_system() const
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

  private:
    /// An initially penetrating u: its M-projection onto K_h, with a
    /// warning.
    void
    project_initial_penetration();

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

    const std::unique_ptr<Triangulation<dim>> triangulation;
    const MappingQ1<dim>                      mapping;
    const MPI_Comm                            comm;
    const ConditionalOStream                  pcout;
    const Scheme                             &scheme;
    const Parameters                          parameters;
    ActiveSetSolver::Parameters               solver_parameters;
    std::unique_ptr<SemiDiscreteSystem<dim>>  system;
    /// 'Contact solver/Preconditioner = multigrid': the same mesh with
    /// linear elements, and the p-multigrid between the two
    std::unique_ptr<SemiDiscreteSystem<dim>> coarse_system;
    std::unique_ptr<StepMultigrid<dim>>      multigrid;
    std::unique_ptr<ContactSetup<dim>>       contact;
    std::unique_ptr<TimeIntegrator>          integrator;
    bool                                     warned_inertia = false;
    /// Whether a trial moved the loads to its end (undone by restore()).
    bool load_stepped = false;
    /// t_n of the last trial step (restore() puts moving obstacles back).
    double step_start_time = 0.;

    // the state
    VectorType u, udot, u_old, udot_old;
    /// the last trial step's, and the initial velocity's (eq. 12c)
    StepReport report, initial_report;
    /// the active sets (displacement, projection) at the start of the
    /// present step
    std::pair<std::vector<char>, std::vector<char>> start_sets;
    /// built by the integrators of earlier meshes
    unsigned int n_earlier_step_matrices = 0;
  };
} // namespace dyncontact

#endif
