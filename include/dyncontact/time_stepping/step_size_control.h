#ifndef dyncontact_time_stepping_step_size_control_h
#define dyncontact_time_stepping_step_size_control_h

#include <dyncontact/time_stepping/step_operators.h>

#include <map>
#include <string>
#include <vector>

namespace dyncontact
{
  /**
   * The estimates of 'Time step control = adaptive' (doc/running.md,
   * "Adaptive time steps"); SimulationControl owns tau and acts on them.
   *
   * Event location. The complementarity of a contact row changes sign
   * inside a step when the row comes into contact (gap g_p - (C u)_p from
   * > 0 to 0) or is released (force from > 0 to 0). Located are, with
   * @p every_row false, the onset of contact (no row active at t_n) and
   * the separation (no row active at the trial's end), not each node of a
   * contact zone that grows or shrinks; with @p every_row true each row's
   * event. event_fraction()
   * interpolates linearly between the start of the step and its trial end:
   * for a new contact the constraint value c_p = (C u - g)_p of u^n and of
   * the constant-velocity prediction u^n + tau udot^n (or, without an
   * approaching velocity, the trial's penetration mu_p / S_ee that the
   * multiplier stands for); for a release the row's force at t_n and the
   * force -2/tau^2 S_ee gap_p that the trial's opened gap stands for.
   * Only rows that are @p settled (in the same state in the step before)
   * are located: a row that chatters (in and out of contact from step to
   * step, as N-CI's do) would otherwise shorten every step.
   *
   * Error estimate. The local error of the trapezoidal (Newmark
   * beta = 1/4) step is tau^3/12 times the third derivative; with the mean
   * accelerations a_n = (udot^{n+1} - udot^n) / tau_n of two steps,
   *   eta_n = tau_n ||a_n - a_{n-1}||_M / (6 (1 + tau_{n-1}/tau_n) V),
   * the step's velocity error relative to the velocity scale V (the
   * largest ||udot||_M of the run so far).
   */
  class StepSizeControl
  {
  public:
    /// The fraction in (0, 2] of the trial step (of length trial.tau,
    /// with the @p operators of that tau; from u_old, udot_old
    /// with @p active_before and the rows' forces @p forces_before to the
    /// trial @p u with @p trial) at which the first contact event is
    /// predicted, over all ranks: in (0, 1] inside the step, in (1, 2) in
    /// the step after it (which N-CS++'s projection looks at); 2 if none is
    /// predicted after the first hundredth of the step. The
    /// SimulationControl decides where the step ends.
    static double
    event_fraction(const StepOperators       &operators,
                   const ContactRowOperator  &row_operator,
                   const std::vector<char>   &active_before,
                   const std::vector<char>   &settled,
                   const std::vector<double> &forces_before,
                   const VectorType          &u_old,
                   const VectorType          &udot_old,
                   const VectorType          &u,
                   const StepReport          &trial,
                   const bool                 every_row,
                   const MPI_Comm             comm);

    /// eta of the step from @p udot_old to @p udot with @p tau (0 for the
    /// first step, after a mesh change or a resume without history); keeps
    /// the velocities' norms for accept().
    double
    estimate(const StepOperators &operators,
             const VectorType    &udot_old,
             const VectorType    &udot,
             const double         tau);

    /// The step just estimated is accepted with estimate @p eta: keeps its
    /// mean acceleration. Returns whether tau may grow (the last two
    /// estimates below @p tolerance / 8).
    bool
    accept(const VectorType &udot_old,
           const VectorType &udot,
           const double      tau,
           const double      eta,
           const double      tolerance);

    /// Forgets the last acceleration (the mesh changed).
    void
    reset()
    {
      has_history = false;
      n_small     = 0;
    }

    /// The last mean acceleration (zero without history), for checkpoints.
    const VectorType &
    get_acceleration() const
    {
      return acceleration;
    }

    void
    save(std::map<std::string, std::string> &state) const;
    /// @p acceleration: the checkpoint's (on the present mesh).
    void
    load(const std::map<std::string, std::string> &state,
         const VectorType                         &acceleration);

    /// Steps shortened to a located event, and steps repeated because
    /// their estimate exceeded the tolerance (kept in checkpoints).
    unsigned int located_events = 0;
    unsigned int repeated_steps = 0;

  private:
    VectorType acceleration;
    /// ||udot_old||_M and ||udot||_M of the step last estimated
    double       velocity_norms[2] = {0., 0.};
    double       previous_tau      = 0.;
    double       velocity_scale    = 0.;
    bool         has_history       = false;
    unsigned int n_small           = 0;
  };
} // namespace dyncontact

#endif
