#ifndef dyncontact_time_integrator_h
#define dyncontact_time_integrator_h

#include <dyncontact/active_set_solver.h>

#include <string>

namespace dyncontact
{
  enum class Scheme
  {
    contact_implicit,            // N-CI, eq. (11)
    contact_stabilized,          // N-CS, Deuflhard-Krause-Ertel 2007
    improved_contact_stabilized, // N-CS++, eq. (12)
    quasi_static                 // min 1/2 v^T A v - f^T v on K_h
  };

  Scheme
  scheme_from_string(const std::string &name);

  std::string
  to_string(const Scheme scheme);

  /// The matrices and the load of the semi-discrete problem, assembled once
  /// per mesh. B is nullptr for an elastic body.
  struct SemiDiscreteSystem
  {
    const MatrixType *M           = nullptr;
    const MatrixType *A           = nullptr;
    const MatrixType *B           = nullptr;
    const VectorType *f           = nullptr;
    bool              lumped_mass = true;
  };

  /// What one step reports to the diagnostics.
  struct StepReport
  {
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
  };

  /**
   * The three Newmark schemes of ALGORITHMS.md section 4 on the algebraic
   * level. Each step is a short function of (u^n, udot^n) that reads like its
   * equations. With
   *   S = M + tau^2/4 A + tau/2 B,
   *   r(w) = M w - tau^2/4 A u^n + tau/2 B u^n + tau^2/2 f,
   *   P(w) = argmin_{Cv<=g} 1/2 (v-w)^T M (v-w)   (eq. 15),
   * the displacement step is argmin_{Cv<=g} 1/2 v^T S v - r(w)^T v.
   */
  class TimeIntegrator
  {
  public:
    TimeIntegrator(const Scheme                          scheme,
                   const double                          tau,
                   const SemiDiscreteSystem             &system,
                   const ActiveSetSolver::Parameters    &solver_parameters,
                   const IndexSet                       &locally_owned,
                   const IndexSet                       &locally_relevant,
                   const AffineConstraints<double>      &mesh_constraints,
                   const ContactRows                    &rows,
                   const std::vector<std::vector<bool>> &constant_modes,
                   const MPI_Comm                        comm);

    /// Initial velocity: N-CS++ replaces udot_0 by (P(u0 + tau udot_0) -
    /// u0)/tau (eq. 12c); the other schemes keep it.
    StepReport
    initialize(const VectorType &u, VectorType &udot);

    /// Advances (u, udot) from t_n to t_{n+1}.
    StepReport
    step(VectorType &u, VectorType &udot);

    /// u <- P(u), the M-projection onto K_h (after a mesh transfer).
    void
    project_onto_constraints(VectorType &u);

    /// Sets the active sets the next solves start from (displacement step
    /// and projection; the second defaults to the first).
    void
    warm_start(const std::vector<char> &active,
               const std::vector<char> &projection = {});

    /// The warm-start active sets (displacement step, projection).
    std::pair<std::vector<char>, std::vector<char>>
    active_sets() const
    {
      return {displacement_active, projection_active};
    }

    double
    time_step() const
    {
      return tau;
    }

    /// Factor from a multiplier mu_p to the contact force: 2/tau^2 for the
    /// dynamic schemes (eq. 13), 1 for the static problem.
    double
    force_factor() const
    {
      return scheme == Scheme::quasi_static ? 1. : 2. / (tau * tau);
    }


  private:
    /// r(w) of the displacement step.
    void
    make_rhs(const VectorType &w, const VectorType &u, VectorType &r) const;

    /// v = argmin_{Cv<=g} 1/2 v^T S v - r^T v (v is the initial guess).
    void
    solve_displacement(const VectorType &r, VectorType &v, StepReport &report);

    /// v = P(w); returns the rows where the projection was active.
    void
    project(const VectorType &w, VectorType &v, StepReport &report);

    const Scheme             scheme;
    const double             tau;
    const SemiDiscreteSystem system;
    MatrixType               S;
    /// static: A + eps M, an SPD matrix for AMG (A alone may be singular)
    MatrixType         preconditioner_matrix;
    ActiveSetSolver    displacement_solver;
    ActiveSetSolver    projection_solver;
    const ContactRows *rows;
    // warm starts of the two active-set solvers
    std::vector<char> displacement_active;
    std::vector<char> projection_active;
  };
} // namespace dyncontact

#endif
