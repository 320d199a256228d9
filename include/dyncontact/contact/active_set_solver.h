#ifndef dyncontact_active_set_solver_h
#define dyncontact_active_set_solver_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dyncontact/contact/contact_row_operator.h>
#include <dyncontact/contact/contact_rows.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;
  using MatrixType = TrilinosWrappers::SparseMatrix;

  /// The diagonal of @p matrix as a vector of its row partitioning (one
  /// pass over Epetra's rows).
  VectorType
  matrix_diagonal(const MatrixType &matrix);



  /**
   * Solves   min 1/2 v^T H v - r^T v   subject to   C v <= g
   * (ALGORITHMS.md section 3) by the primal-dual active-set method
   * (semismooth Newton, as in deal.II's step-41/42). Each active row
   * eliminates one slave component through an AffineConstraints line merged
   * with the hanging-node and Dirichlet constraints; the condensed SPD
   * problem T^T H T x = T^T (r - H k) is solved by CG, preconditioned by AMG
   * or Jacobi built once from H itself, so that nothing is assembled again
   * when the active set changes.
   *
   * The solver knows nothing about time: the time integrators use one
   * instance with H = S for the displacement step and one with H = M for the
   * L2 projection.
   */
  class ActiveSetSolver
  {
  public:
    struct Parameters
    {
      unsigned int max_iterations   = 50;
      double       linear_tolerance = 1e-12;
      /// CG's tolerance in a time step, relative to its start's residual
      double       step_tolerance        = 1e-6;
      unsigned int max_linear_iterations = 2000;
      /// AMG's near-null space: the rigid translations only, or also the
      /// infinitesimal rotations.
      bool amg_rotations = false;

      /// AMG's prolongator: the tentative (unsmoothed) aggregation, or
      /// smoothed aggregation (ML's damping factor 4/3).
      bool amg_smoothed_prolongator = false;

      /// CG's preconditioner for a matrix H that is not diagonal.
      enum class Preconditioner
      {
        /// Jacobi where the condition number of H scaled by its diagonal
        /// is at most jacobi_condition_bound for certain, AMG otherwise
        automatic,
        amg,
        jacobi,
        /// a two-level p-multigrid of the matrix-free S: Chebyshev
        /// smoothing on S's diagonal, AMG on S of linear elements
        multigrid
      };
      Preconditioner preconditioner = Preconditioner::automatic;

      /// Whether the time step's matrix S is applied without being
      /// assembled (then preconditioned by Jacobi; 'Step matrix').
      bool matrix_free_step = false;
      /// The bound of the condition number of diag(H)^{-1} H up to which
      /// 'automatic' takes Jacobi: CG on H then needs at most about
      /// sqrt(100)/2 ln(2 sqrt(100)/1e-12) = 150 iterations for a relative
      /// residual of 1e-12, on any mesh.
      static constexpr double jacobi_condition_bound = 100.;

      /// Declares subsection "Contact solver".
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// The energy monitor's tolerance (relative to the energy scale)
      /// that the step tolerance allows: 1e-2 times it, within
      /// [1e-9, 1e-4]. (A time step's residual does no work on its
      /// increment, whatever the tolerance: what remains of it in the
      /// balance is the work of the multipliers on moving obstacles and
      /// prescribed displacements, and a lumped mass's L2 projection that
      /// is a solve, with two bodies or hanging nodes.)
      double
      energy_tolerance() const
      {
        return std::min(1e-4, std::max(1e-9, 1e-2 * step_tolerance));
      }
    };

    /// How a solve ended. A failure is reported, never thrown: the time
    /// step control decides what to do (retry with a smaller step, or stop
    /// with a checkpoint and a message).
    enum class Status
    {
      converged,
      /// the active set still changed after the maximum number of iterations
      active_set_not_converged,
      /// CG did not reach its tolerance within its maximum iterations
      linear_solver_failed
    };

    struct Result
    {
      Status       status            = Status::converged;
      unsigned int iterations        = 0;
      unsigned int linear_iterations = 0;
      /// max_p |min(mu_p / c_p, g_p - (C v)_p)| at the last iterate (m)
      double residual = 0.;
      /// CG's residual when it failed
      double linear_residual = 0.;
      /// whether the iteration revisited an active set (and was damped)
      bool cycled = false;

      bool
      converged() const
      {
        return status == Status::converged;
      }

      /// What went wrong, naming the parameter that limits it; empty when
      /// converged.
      std::string
      failure() const;
    };

    ActiveSetSolver(const Parameters &parameters, const MPI_Comm comm);

    /**
     * Sets the partitioning, the mesh constraints (hanging nodes, Dirichlet;
     * homogeneous) and the contact rows. Called once per mesh.
     */
    void
    reinit(const IndexSet                  &locally_owned,
           const IndexSet                  &locally_relevant,
           const AffineConstraints<double> &mesh_constraints,
           const ContactRows               &rows);

    /**
     * Sets H and CG's preconditioner for it, built once: Jacobi (H's
     * diagonal), or AMG (of @p preconditioner_matrix if given), as
     * 'Contact solver/Preconditioner' says.
     *
     * For 'automatic', @p lumped_mass_ratio is max_i H_ii / M_ii where
     * H = M + K with M a lumped (diagonal) mass and K positive
     * semidefinite; infinite if H is not of that form. With D = diag(H),
     * x^T H x >= x^T M x >= x^T D x / lumped_mass_ratio, and by Gershgorin
     * the largest eigenvalue of D^{-1} H is at most max_i sum_j |H_ij| / H_ii:
     * their product bounds the condition number of D^{-1} H, and Jacobi is
     * taken when that bound is at most Parameters::jacobi_condition_bound.
     */
    void
    set_matrix(
      const MatrixType &H,
      const MatrixType *preconditioner_matrix = nullptr,
      const double lumped_mass_ratio = std::numeric_limits<double>::infinity());

    /// The name of CG's preconditioner: "AMG", "Jacobi" or "p-multigrid".
    std::string
    preconditioner_name() const
    {
      return amg ? "AMG" : H_preconditioner ? "p-multigrid" : "Jacobi";
    }

    /// The bound of the condition number of diag(H)^{-1} H that
    /// 'automatic' decided by (infinite if it was not computed).
    double
    get_condition_bound() const
    {
      return condition_bound;
    }

    /// y = H x for an H that is not stored.
    using Operator = std::function<void(VectorType &y, const VectorType &x)>;

    /**
     * Sets H, applied by @p vmult without a matrix, with its @p diagonal
     * (copied); CG is preconditioned by @p preconditioner, a symmetric
     * positive definite approximation of H^{-1} on the space of the mesh
     * constraints, if given, else by Jacobi.
     */
    void
    set_operator(const Operator   &vmult,
                 const VectorType &diagonal,
                 const Operator   &preconditioner = Operator());

    /**
     * Sets H = diag(@p diagonal), a lumped mass (copied);
     * Jacobi is used, and with rows that only touch unconstrained slave DoFs
     * the solve is pointwise.
     */
    void
    set_diagonal_matrix(const VectorType &diagonal);

    /**
     * AMG's near-null space: the rigid translations (per component, whether
     * a locally owned DoF belongs to it, as DoFTools::extract_constant_modes
     * gives them) and, if not empty, the infinitesimal rotations (their
     * values at the locally owned DoFs).
     */
    struct NearNullSpace
    {
      std::vector<std::vector<bool>> translations;
      std::vector<VectorType>        rotations;
    };

    /// Sets AMG's near-null space (kept by reference: @p modes must outlive
    /// this solver); call before set_matrix().
    void
    set_near_null_space(const NearNullSpace &modes)
    {
      near_null_space = &modes;
    }

    /**
     * Solves the constrained problem for right-hand side @p r. On entry
     * @p v is the initial guess, on exit the solution. @p active holds one
     * flag per contact row: the warm start on entry, the final active set on
     * exit. @p multipliers receives mu_p = nu_p . (r - H v)|_p per row
     * (zero for inactive rows); both for this rank's rows. The ranks agree
     * on convergence and on a damped (cycling) iteration through scalar
     * reductions only.
     */
    Result
    solve(const VectorType    &r,
          VectorType          &v,
          std::vector<char>   &active,
          std::vector<double> &multipliers,
          const VectorType    *origin = nullptr) const;

  private:
    void
    make_constraints(const std::vector<char>   &active,
                     AffineConstraints<double> &constraints,
                     const bool                 homogeneous) const;

    /**
     * The homogeneous constraints T of one solve on an active set, and
     * their owned lines in the local indices of the owned vectors, for what
     * CG does with them at every iteration (T x, T^T z, zeroing) without
     * deal.II's access by global index (an Epetra lookup per entry) and
     * without communication. That is taken where no rank has a line with
     * an entry owned elsewhere (@p local, the same on every rank);
     * otherwise the AffineConstraints are used. Both give the same numbers,
     * summed in the same order.
     */
    struct Condensation
    {
      /// Collective. With @p inhomogeneous, the same constraints with their
      /// inhomogeneities k (v = T x + k): kept where its owned lines are
      /// those of @p constraints, for distribute_inhomogeneous().
      void
      reinit(const AffineConstraints<double> &constraints,
             const VectorType                &layout,
             const IndexSet                  &owned,
             const MPI_Comm                   comm,
             const AffineConstraints<double> *inhomogeneous = nullptr);

      const AffineConstraints<double> *constraints = nullptr;
      bool                             local       = false;
      /// the owned lines' local indices; the entries of line l are
      /// [start[l], start[l + 1]) of columns (local indices) and values
      std::vector<int>          rows;
      std::vector<unsigned int> start;
      std::vector<int>          columns;
      std::vector<double>       values;
      /// T^T: each entry's slot among the distinct columns (slot_columns),
      /// whose additions are summed in a slot before they are added to the
      /// column, as deal.II's vector of additions does
      std::vector<unsigned int>   slots;
      std::vector<int>            slot_columns;
      mutable std::vector<double> slot_sums;
      /// each owned line's inhomogeneity, where local and reinit() was
      /// given the inhomogeneous constraints (on every rank alike); then
      /// neither AffineConstraints is read again, and constraints_of()
      /// clears both
      bool                inhomogeneities_local = false;
      std::vector<double> inhomogeneities;
    };

    /**
     * The constraints of the active set of the last solve on one, kept for
     * the next solve on the same set: they depend only on the set, the
     * rows and the mesh constraints, which change only with reinit(), and
     * most steps solve on the active set of the step before. Building and
     * closing them, with their Condensation, at every solve took a quarter
     * of the solves' time on adaptive meshes.
     */
    struct ActiveSetConstraints
    {
      ActiveSetConstraints() = default;
      /// (the Condensation points into this object)
      ActiveSetConstraints(const ActiveSetConstraints &) = delete;
      ActiveSetConstraints &
      operator=(const ActiveSetConstraints &) = delete;

      std::vector<char> active;
      /// ContactRows::gap_version of the gaps they were made with
      unsigned long             gap_version = 0;
      AffineConstraints<double> constraints, homogeneous_constraints;
      Condensation              homogeneous;
    };

    /// The constraints of @p active: those of the last solve if it was on
    /// the same set on every rank (collective), else built anew.
    const ActiveSetConstraints &
    constraints_of(const std::vector<char> &active,
                   const VectorType        &layout) const;

    /// v <- T v + k on the constrained entries (AffineConstraints::
    /// distribute() of the inhomogeneous constraints, summed as it does).
    void
    distribute_inhomogeneous(const ActiveSetConstraints &constraints,
                             VectorType                 &v) const;

    /// y = T^T H T x on unconstrained entries, y_i = x_i on constrained ones.
    void
    vmult_condensed(const Condensation &homogeneous,
                    VectorType         &y,
                    const VectorType   &x) const;

    /// y = P^{-1} x (AMG, or Jacobi) with the constrained entries zero.
    void
    precondition_condensed(const Condensation &homogeneous,
                           VectorType         &y,
                           const VectorType   &x) const;

    /// Sets the constrained entries of @p x to zero.
    void
    zero_constrained(const Condensation &homogeneous, VectorType &x) const;

    /// The next active set: row p is active where mu_p + c_p (C v - g)_p >
    /// c_p delta; the displacement tolerance delta (returned in @p delta,
    /// from the gaps and v) keeps round-off from flipping rows that sit
    /// exactly on the constraint. The complementarity residual goes into
    /// @p result.
    std::vector<char>
    next_active_set(const VectorType          &v,
                    const std::vector<double> &multipliers,
                    const std::vector<double> &violation,
                    double                    &delta,
                    Result                    &result) const;

    /// y = T^T z: adds constrained entries to the entries they depend on.
    void
    transpose_distribute(const Condensation &homogeneous, VectorType &z) const;
    /// z_j += c_ij z_i for every owned constrained entry i of @p constraints
    /// and its entries (c_ij, j), possibly owned elsewhere (collective).
    void
    add_to_masters(const AffineConstraints<double> &constraints,
                   VectorType                      &z) const;

    /// The vectors of the active-set iteration, made once per solve().
    struct Scratch
    {
      /// (@p with_origin: also the vectors of the correction along the
      /// increment)
      Scratch(const VectorType &r, const bool with_origin)
        : k(r)
        , b(r)
        , x(r)
        , residual(r)
      {
        if (with_origin)
          {
            x_origin.reinit(r);
            direction.reinit(r);
          }
      }
      VectorType k, b, x, residual;
      /// the origin's condensed part and a direction (origin given)
      VectorType x_origin, direction;
    };

    /// One equality-constrained solve of the active-set iteration: v with
    /// the rows of @p active as equalities (CG on the condensed system,
    /// warm started from v). False (with the result's status set) if CG
    /// fails.
    bool
    solve_on_active_set(const std::vector<char> &active,
                        const bool               any_active,
                        const VectorType        &r,
                        const double             r_norm,
                        const VectorType        *origin,
                        VectorType              &v,
                        Result                  &result,
                        Scratch                 &scratch) const;

    /// Moves the CG solution @p x of the condensed system (right-hand side
    /// @p b) along the line from the origin's condensed part (in @p
    /// scratch) to where the residual is orthogonal to x - x_origin.
    void
    correct_along_increment(const Condensation &homogeneous,
                            const VectorType   &b,
                            VectorType         &x,
                            Scratch            &scratch) const;

    /// The multipliers of the active rows, from the residual r - H v.
    void
    compute_multipliers(const std::vector<char> &active,
                        const bool               any_active,
                        const VectorType        &r,
                        const VectorType        &v,
                        std::vector<double>     &multipliers,
                        Scratch                 &scratch) const;

    /// Against cycling: @p new_active becomes @p active with only the row
    /// (over all ranks) that violates its condition the most changed.
    void
    change_one_row(const std::vector<char>   &active,
                   const std::vector<double> &multipliers,
                   const std::vector<double> &violation,
                   std::vector<char>         &new_active) const;

    Result
    solve_pointwise(const VectorType    &r,
                    VectorType          &v,
                    std::vector<char>   &active,
                    std::vector<double> &multipliers) const;

    const Parameters parameters;
    const MPI_Comm   comm;

    IndexSet                  locally_owned;
    AffineConstraints<double> mesh_constraints;
    /// Whether a line of mesh_constraints has entries on some rank (hanging
    /// nodes; Dirichlet lines have none).
    bool               mesh_has_hanging_nodes = false;
    const ContactRows *rows                   = nullptr;
    ContactRowOperator row_operator;

    /// H, nullptr if it is diagonal (then given by @p diagonal alone) or
    /// applied by H_operator.
    const MatrixType *H = nullptr;
    Operator          H_operator;
    /// CG's preconditioner for H_operator, if not Jacobi
    Operator H_preconditioner;
    bool     pointwise = false;
    /// Diagonal of H (owned entries) and its value at each row's
    /// eliminated DoF (the scaling c of the active-set criterion); the
    /// inverse of the diagonal for Jacobi.
    VectorType          diagonal;
    VectorType          inverse_diagonal;
    std::vector<double> row_scaling;

    /// The part of set_matrix() and set_diagonal_matrix() that only needs
    /// the diagonal: row scaling and whether the solve is pointwise.
    void
    set_diagonal_data(const bool is_diagonal);

    /// Jacobi's inverse of the diagonal.
    void
    set_inverse_diagonal();

    /// max_i sum_j |H_ij| / H_ii over all rows (collective).
    double
    gershgorin_bound(const MatrixType &H) const;

    /// set_matrix()'s bound of the condition number of diag(H)^{-1} H.
    double condition_bound = std::numeric_limits<double>::infinity();

    /// y = H x.
    void
    vmult_H(VectorType &y, const VectorType &x) const;

    /// Work vectors of the condensed operator, made once per mesh: T x, and
    /// the additions of T^T to entries owned elsewhere (writable ghosts).
    mutable VectorType Tx;
    mutable VectorType additions;
    /// reset by reinit()
    mutable std::unique_ptr<ActiveSetConstraints> last_constraints;
    const NearNullSpace                          *near_null_space = nullptr;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
  };



  /**
   * Trilinos ML's AMG of @p matrix with this program's settings (no
   * dropping, 2 Chebyshev sweeps, the near-null space @p modes if not null,
   * the tentative prolongator unless @p smoothed_prolongator): the
   * preconditioner of ActiveSetSolver, and the coarse level of the
   * p-multigrid of a matrix-free step matrix.
   */
  std::unique_ptr<TrilinosWrappers::PreconditionAMG>
  make_amg(const MatrixType                     &matrix,
           const ActiveSetSolver::NearNullSpace *modes,
           const bool                            smoothed_prolongator);
} // namespace dyncontact

#endif
