#ifndef dyncontact_time_stepping_integrators_h
#define dyncontact_time_stepping_integrators_h

#include <dyncontact/time_stepping/step_operators.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
  /// One scheme's step (or initial velocity): advances (u, udot) in place.
  using StepFunction = void (*)(StepOperators &operators,
                                VectorType    &u,
                                VectorType    &udot,
                                StepReport    &report);

  /**
   * A time integrator: its name in the prm, a description, whether it is the
   * static problem, its step and (optionally) its initial velocity. The
   * schemes are named functions in source/time_stepping/integrators.cc
   * (step_nci, step_ncs, step_ncspp with initialize_ncspp, step_static), each
   * reading like its equations on the StepOperators; a new scheme is one
   * such function and one line in schemes().
   */
  struct Scheme
  {
    std::string  name;
    std::string  description;
    bool         is_static  = false;
    StepFunction initialize = nullptr;
    StepFunction step       = nullptr;
  };

  /// All schemes, in the order of the documentation.
  const std::vector<Scheme> &
  schemes();

  /// The scheme of this name; throws with the list of names otherwise.
  const Scheme &
  scheme_by_name(const std::string &name);

  /**
   * A scheme with its operators on one mesh: the object the time loop steps
   * with. It stores no time step: each step is handed its tau (the
   * SimulationControl's), and the operators keep the step matrices of the
   * last tau levels. Rebuilt when the mesh changes (the active sets carry
   * over through warm_start()).
   */
  class TimeIntegrator
  {
  public:
    /// @p tau: the step matrix built now (the first step's).
    TimeIntegrator(const Scheme             &scheme,
                   const double              numerical_dissipation,
                   const double              tau,
                   const StepOperatorInputs &inputs);

    /// The initial velocity of the scheme with the first step's @p tau
    /// (N-CS++: eq. 12c; the others keep udot_0).
    StepReport
    initialize(const double tau, VectorType &u, VectorType &udot);

    /// Advances (u, udot) from t_n to t_{n+1} = t_n + @p tau. The step
    /// matrix S of a tau not seen before is built now; @p is_level: it is
    /// kept for later steps (StepOperators::set_time_step()).
    StepReport
    step(const double tau,
         const bool   is_level,
         VectorType  &u,
         VectorType  &udot);

    /// u <- P(u), the M-projection onto K_h (after a mesh transfer).
    void
    project_onto_constraints(VectorType &u);

    /**
     * After a mesh transfer: if u violates the new K_h (new nodes on a
     * curved surface, coarsened nodes), u <- P(u); the active sets restart
     * from the rows that touch. Returns the largest violation before the
     * projection (m).
     */
    double
    restore_constraints(VectorType &u, const ContactRowOperator &rows);

    /// Sets the active sets the next solves start from (displacement step
    /// and projection; the second defaults to the first).
    void
    warm_start(const std::vector<char> &active,
               const std::vector<char> &projection = {});

    /// The warm-start active sets (displacement step, projection).
    std::pair<std::vector<char>, std::vector<char>>
    active_sets() const
    {
      return {operators.displacement_active, operators.projection_active};
    }

    /**
     * The warm-start active sets (checkpoints) as a nodal vector, so that
     * they travel with the distributed mesh data and no rank gathers the
     * rows of others: at the eliminated DoF of each row, 1 if it is active
     * in the displacement step, plus 2 if in the projection.
     */
    void
    save_active_sets(VectorType &flags) const;
    void
    load_active_sets(const VectorType &flags);

    /// The active sets (displacement step, projection) that @p flags of
    /// save_active_sets() hold on @p rows.
    static std::pair<std::vector<char>, std::vector<char>>
    decode_active_sets(const ContactRows &rows, const VectorType &flags);

    const Scheme &
    get_scheme() const
    {
      return scheme;
    }

    /// max_i S_ii / M_ii of the step matrix S = M + tau^2/4 A + tau/2 B of
    /// the last step (or of the tau the integrator was made with).
    double
    inertia_ratio() const
    {
      return operators.inertia_ratio();
    }

    /// A warning if S keeps the mass only to a poor relative accuracy (eps
    /// times inertia_ratio() above 1e-6: momentum and energy drift by that
    /// much per step), else "".
    std::string
    inertia_warning() const;

    /// CG's preconditioner for the current step (StepOperators).
    std::string
    preconditioner_name() const
    {
      return operators.preconditioner_name();
    }

    /// StepOperators::matrix_free().
    bool
    matrix_free() const
    {
      return operators.matrix_free();
    }

    /// StepOperators::condition_bound().
    double
    condition_bound() const
    {
      return operators.condition_bound();
    }

    /// StepOperators::set_step_times(): t_n and t_{n+1} of the next step.
    void
    set_step_times(const double start, const double end)
    {
      operators.set_step_times(start, end);
    }

    /// The operators (for the step control's estimates).
    const StepOperators &
    get_operators() const
    {
      return operators;
    }


  private:
    /// A report of a step of @p tau with every per-row list sized and zero.
    StepReport
    empty_report(const double tau) const;

    const Scheme   scheme;
    StepOperators  operators;
    const MPI_Comm comm;
  };
} // namespace dyncontact

#endif
