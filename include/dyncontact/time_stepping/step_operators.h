#ifndef dyncontact_time_stepping_step_operators_h
#define dyncontact_time_stepping_step_operators_h

#include <dyncontact/contact/active_set_solver.h>
#include <dyncontact/discretization/semi_discrete_system.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
  /// What one step reports to the diagnostics and to the step control.
  struct StepReport
  {
    /// The step's length tau (s; the static problem: Time step).
    double tau = 0.;
    /// Factor from a multiplier mu_p to the contact force: 2/tau^2 for the
    /// dynamic schemes (eq. 13), 1 for the static problem.
    double                  force_factor = 0.;
    ActiveSetSolver::Result displacement_solve;
    ActiveSetSolver::Result projection_solve;
    /// Active rows and multipliers of the displacement step (12d)/(11c).
    std::vector<char>   active;
    std::vector<double> multipliers;
    /// Rows where the L2 projection was active (12f; for N-CS its predictor).
    std::vector<char> projection_active;
    /// Rows of Gamma*_{h,C} (eq. 40): projection active, displacement not.
    std::vector<char> critical;
    /// ||udot^{n+1} - udot_pred^{n+1}||_M (N-CS++), resp. the size of the
    /// predictor's correction for N-CS; zero for N-CI.
    double velocity_correction = 0.;
    /// The adaptive step control's error estimate eta of the step (0 with
    /// fixed tau; StepSizeControl).
    double error_estimate = 0.;
    /// theta (du)^T A (du), what the step's numerical dissipation theta took
    /// (J; 0 for theta = 0).
    double numerical_dissipation = 0.;
    /// With rigid obstacles that move: the work of their contact forces on
    /// the bodies in the step (J, summed over the ranks; doc/algorithms.md,
    /// "Rigid obstacles that move"), and the multipliers of the L2
    /// projection it is computed from.
    double              obstacle_work = 0.;
    std::vector<double> projection_multipliers;

    /// Whether both constrained problems of the step converged.
    bool
    converged() const
    {
      return displacement_solve.converged() && projection_solve.converged();
    }

    /// What failed (empty if the step converged).
    std::string
    failure() const
    {
      return displacement_solve.converged() ? projection_solve.failure() :
                                              displacement_solve.failure();
    }
  };

  /**
   * What the step operators are built from: the semi-discrete system's
   * matrices, its index sets and constraints, the contact rows and the
   * active-set solver's parameters (StepOperators keeps copies of the
   * matrices' handles, the parameters and the index sets, and refers to the
   * constraints and the rows).
   */
  struct StepOperatorInputs
  {
    const SystemMatrices                 &system;
    const ActiveSetSolver::Parameters    &solver_parameters;
    const IndexSet                       &locally_owned;
    const IndexSet                       &locally_relevant;
    const AffineConstraints<double>      &mesh_constraints;
    const ContactRows                    &rows;
    const ActiveSetSolver::NearNullSpace &near_null_space;
    MPI_Comm                              comm;
    /// With rigid obstacles that move: sets the rows' gaps to those at a
    /// time t; empty otherwise.
    std::function<void(double)> move_obstacles = {};
  };

  /**
   * The operators a time step is written with (ALGORITHMS.md section 4), on
   * the algebraic level, with the numerical dissipation theta (0 in the
   * paper):
   *   S = M + (1/4 + theta/2) tau^2 A + tau/2 B      (static: S = A),
   *   r(w) = M w - (1/4 - theta/2) tau^2 A u^n + tau/2 B u^n + tau^2/2 f,
   *   the displacement step argmin_{Cv<=g} 1/2 v^T S v - r^T v,
   *   P(w) = argmin_{Cv<=g} 1/2 (v-w)^T M (v-w)   (eq. 15).
   * Each constrained problem is solved by its own active-set solver, warm
   * started from its last active set.
   */
  class StepOperators
  {
  public:
    StepOperators(const bool                is_static,
                  const double              numerical_dissipation,
                  const double              tau,
                  const StepOperatorInputs &inputs);

    /// Not copied nor moved: a matrix-free S refers to these operators.
    StepOperators(const StepOperators &) = delete;
    StepOperators &
    operator=(const StepOperators &) = delete;

    double
    tau() const
    {
      return current->tau;
    }

    /// The numerical dissipation theta (Time integration/Numerical
    /// dissipation): each step dissipates theta (du)^T A (du).
    double
    numerical_dissipation() const
    {
      return theta;
    }

    /// The load at the step's end, f(t_{n+1}) (the static problem's).
    const VectorType &
    load() const
    {
      return *system.f_end;
    }

    /// r = r(w) for the step from u = u^n.
    void
    rhs(const VectorType &w, const VectorType &u, VectorType &r) const;

    /// v = argmin_{Cv<=g} 1/2 v^T S v - r^T v (v is the initial guess);
    /// fills the report's displacement solve, active set and multipliers.
    void
    solve_displacement(const VectorType &r,
                       VectorType       &v,
                       StepReport       &report,
                       const VectorType *origin = nullptr);

    /// v = P(w) (the initial guess is w); fills the report's projection.
    /// @p origin: see solve_displacement(); not used with a consistent or
    /// blended mass, whose CG stops at Linear solver tolerance.
    void
    project(const VectorType &w,
            VectorType       &v,
            StepReport       &report,
            const VectorType *origin = nullptr);

    /// sqrt(x^T M x).
    double
    mass_norm(const VectorType &x) const;

    /// With Dirichlet data that move: the force of the prescribed DoFs on
    /// the body in the last displacement step, (2/tau^2) (S v - r) there
    /// (the static problem: A v - f), a hanging child's share passed to
    /// its parents; zero elsewhere. Empty without such data.
    const VectorType &
    prescribed_reaction() const
    {
      return reaction;
    }

    /// The tolerances of the contact solves.
    const ActiveSetSolver::Parameters &
    get_solver_parameters() const
    {
      return solver_parameters;
    }

    /// A u, kept in the system's CachedProduct: computed only if u is not
    /// the vector of the last product (the reference is valid until the
    /// next product).
    const VectorType &
    stiffness_product(const VectorType &u) const
    {
      return system.stiffness_vmult(u);
    }

    std::size_t
    n_rows() const
    {
      return rows->size();
    }

    /// This rank's contact rows.
    const ContactRows &
    contact_rows() const
    {
      return *rows;
    }

    /// max_i S_ii / M_ii (1 for the static problem): S keeps the mass only
    /// to a relative accuracy of about this times the machine epsilon.
    double
    inertia_ratio() const
    {
      return current->inertia_ratio;
    }

    /// CG's preconditioner for the current step matrix: "AMG", "Jacobi"
    /// or "p-multigrid".
    std::string
    preconditioner_name() const
    {
      return current->solver->preconditioner_name();
    }

    /// The bound of the condition number of the current S scaled by its
    /// diagonal that 'Contact solver/Preconditioner = automatic' decided by
    /// (infinite if not computed).
    double
    condition_bound() const
    {
      return current->solver->get_condition_bound();
    }

    /// The step's start and end times t_n and t_{n+1} (s): the gaps of
    /// rigid obstacles that move depend on them.
    void
    set_step_times(const double start, const double end)
    {
      t_start = start;
      t_end   = end;
    }

    double
    step_start() const
    {
      return t_start;
    }

    double
    step_end() const
    {
      return t_end;
    }

    /// Whether rigid obstacles move (the rows' gaps depend on t).
    bool
    obstacles_move() const
    {
      return static_cast<bool>(move_obstacles);
    }

    /// With rigid obstacles that move: the rows' gaps at time @p t (the
    /// constrained problems that follow use them); nothing otherwise.
    void
    constraints_at(const double t) const
    {
      if (move_obstacles)
        move_obstacles(t);
    }

    /// The warm-start active sets (displacement step, projection).
    std::vector<char> displacement_active;
    std::vector<char> projection_active;

    /**
     * Steps with @p tau from now on. S = M + tau^2/4 A + tau/2 B and its
     * AMG are built only for a tau not seen before: the last
     * n_cached_levels levels (@p is_level) are kept, a shortened step's
     * (not a level) only until the next one.
     */
    void
    set_time_step(const double tau, const bool is_level);

    /// S_ii, the step matrix's diagonal at locally owned DoF @p i.
    double
    step_matrix_diagonal(const types::global_dof_index i) const
    {
      return current->diagonal(i);
    }

    /// Whether S is applied without a matrix ('Contact solver/Step matrix').
    bool
    matrix_free() const
    {
      return solver_parameters.matrix_free_step && !is_static;
    }

    /// How many S (with AMG) of tau levels are kept.
    static constexpr unsigned int n_cached_levels = 4;

    /// How many step matrices have been built (one per new tau).
    unsigned int n_step_matrices_built = 0;

  private:
    /// S for one tau with its active-set solver (which holds the AMG).
    struct StepMatrix
    {
      double tau           = 0.;
      double inertia_ratio = 1.;
      /// S, empty where it is applied without a matrix
      MatrixType S;
      /// S's diagonal (owned entries)
      VectorType diagonal;
      /// the matrix-free S x: workspace of (tau^2/4 A + tau/2 B) x
      mutable VectorType stiffness_part;
      /// y = S x without constraints (matrix-free or by the matrix)
      Product S_product;
      /// static: A + eps M, an SPD matrix for AMG (A alone may be singular)
      MatrixType                       preconditioner;
      std::unique_ptr<ActiveSetSolver> solver;
    };

    std::unique_ptr<StepMatrix>
    make_step_matrix(const double tau) const;

    const bool                        is_static;
    const std::function<void(double)> move_obstacles;
    double                            t_start = 0.;
    double                            t_end   = 0.;
    /// theta: A acts on (1/2 + theta) u^{n+1} + (1/2 - theta) u^n
    const double                      theta;
    const SystemMatrices              system;
    const ActiveSetSolver::Parameters solver_parameters;
    const IndexSet                    locally_owned;
    const IndexSet                    locally_relevant;
    /// (must outlive the operators, as the system matrices and rows)
    const AffineConstraints<double>     *mesh_constraints;
    const ActiveSetSolver::NearNullSpace near_null_space;
    const MPI_Comm                       comm;
    /// (see prescribed_reaction())
    VectorType reaction;
    /// the step matrices of tau levels, the most recently used last
    std::vector<std::unique_ptr<StepMatrix>> levels;
    /// a shortened step's matrix (not a level)
    std::unique_ptr<StepMatrix> shortened;
    StepMatrix                 *current = nullptr;
    ActiveSetSolver             projection_solver;
    const ContactRows          *rows;
  };

} // namespace dyncontact

#endif
