#ifndef dyncontact_time_stepping_time_step_controller_h
#define dyncontact_time_stepping_time_step_controller_h

#include <dyncontact/time_stepping/step_size_control.h>
#include <dyncontact/time_stepping/time_integration_parameters.h>

#include <map>
#include <string>
#include <vector>

namespace dyncontact
{
  /**
   * The one owner of the time step tau (doc/algorithms.md, "Adaptive time
   * steps"). The time loop asks it for the tau of a trial step and hands it
   * the trial; it answers accept, or retry (from the start of the step)
   * with the tau it has set: halved after a failed solve or an error
   * estimate above the tolerance, shortened to the predicted moment of a
   * contact event. It holds what these answers depend on: the parameters,
   * the level tau_level and the present tau, the error estimator
   * (StepSizeControl), the contact rows' forces and states of the last
   * accepted step, and the counts of located events and repeated steps;
   * and it saves and loads all of that in checkpoints.
   *
   * With 'Time step control = fixed' every step takes Time step; with
   * 'Time step adaptation' a failed step is retried with tau/2 (down to
   * Time step / 1024). With 'adaptive' tau moves between the levels
   * Time step * 2^k inside [Minimum time step, Maximum time step]; a step
   * that is shortened (to an event, or to End time) is not a level, and
   * the step after it returns to the level.
   *
   * The integrator stores no tau: it is handed the trial's tau with each
   * step, and each StepReport carries the tau of its step.
   */
  class TimeStepController
  {
  public:
    /// Takes and checks Time integration/Time step, Time step adaptation,
    /// Time step control, Event location, Minimum/Maximum time step, Time
    /// step tolerance; @p is_static: one solve, no time step control;
    /// @p end_time (SimulationControl's End time) bounds the number of
    /// steps, and the adaptive control's last step ends there.
    void
    parse_parameters(const TimeIntegrationParameters &parameters,
                     const bool                       is_static,
                     const double                     end_time);

    /// The tau of the next trial (after an accepted step: the level the
    /// next step starts from).
    double
    get_timestep() const
    {
      return tau;
    }

    /// Whether 'Time step control = adaptive'.
    bool
    is_adaptive() const
    {
      return adaptive;
    }

    double
    get_minimum_timestep() const
    {
      return min_time_step;
    }

    double
    get_maximum_timestep() const
    {
      return max_time_step;
    }

    /// Whether the present trial is shortened (to an event or End time):
    /// its step matrix is not kept as a level's.
    bool
    step_is_shortened() const
    {
      return tau != tau_level;
    }

    /// The contact rows changed (a new mesh, or the first one): forgets
    /// the estimates and the rows' last forces and states.
    void
    reset(const std::size_t n_rows);

    /// The adaptive control ends a step at every multiple of @p interval
    /// (0: none) that it would pass (the output times), except where a contact
    /// event lies within the step after that time (N-CS++'s projection
    /// would see it from there): then the step takes its level, and the
    /// time is passed. Fixed steps do not change.
    void
    stop_at_multiples_of(const double interval);

    /// The steps must reach every multiple of @p interval (the times of
    /// reference states, which a writing and a comparing run must both
    /// reach): the adaptive control ends a step there where it would pass
    /// one; a fixed Time step must divide it, or the run stops with a
    /// message naming @p entry (the parameter that sets the interval).
    void
    require_multiples_of(const double interval, const std::string &entry);

    /// A new step from @p time (until a trial is accepted).
    void
    begin_step(const double time);

    /// The tau of the next trial of the present step: get_timestep(), but
    /// a step of the adaptive control that would pass End time or a time
    /// of stop_at_multiples_of() or require_multiples_of() ends there.
    double
    trial_timestep();

    /// The trial failed (a solve did not converge, or the state is not
    /// finite): true, with tau halved for a retry from the start of the
    /// step, where the control allows it (adaptive, or 'Time step
    /// adaptation' down to Time step / 1024); false otherwise.
    bool
    retry_after_failure();

    /// Which contact events the adaptive control locates.
    enum class EventLocation
    {
      none,
      onset_and_separation,
      every_row
    };

    /// What to do with a converged trial step.
    enum class Verdict
    {
      /// keep it
      accept,
      /// repeat it from the start of the step with the new get_timestep()
      retry
    };

    /// The adaptive control's judgement of the converged @p trial from
    /// (@p u_old, @p udot_old) with the active sets @p active_before to
    /// (@p u, @p udot): retry, shortened to a contact event predicted
    /// inside it (once per step) or halved where its error estimate
    /// exceeds the tolerance; otherwise accept, with the trial's error
    /// estimate set. Over all ranks of @p comm. With fixed tau: accept.
    Verdict
    judge(const StepOperators      &operators,
          const ContactRowOperator &row_operator,
          const std::vector<char>  &active_before,
          const VectorType         &u_old,
          const VectorType         &udot_old,
          const VectorType         &u,
          const VectorType         &udot,
          StepReport               &trial,
          const MPI_Comm            comm);

    /// The step that was accepted.
    struct AcceptedStep
    {
      /// its length
      double tau = 0.;
      /// whether tau changed since the step before (t_{n+1} is then
      /// counted from t_n: SimulationControl::advance())
      bool tau_changed = false;
    };

    /// The trial was accepted (after judge(), which keeps the rows' forces
    /// and states for the next step's event location, or with fixed tau):
    /// returns to the level after a shortened step and doubles the level
    /// where the estimates allow it.
    AcceptedStep
    accept();

    /// Steps shortened to a located event, and steps repeated because
    /// their estimate exceeded the tolerance.
    unsigned int
    n_located_events() const
    {
      return estimator.located_events;
    }

    unsigned int
    n_repeated_steps() const
    {
      return estimator.repeated_steps;
    }

    /// Output times passed because a contact event followed (each costs a
    /// trial step).
    unsigned int
    n_passed_output_times() const
    {
      return passed_output_times;
    }

    /**
     * tau, its level and the estimator's scalars into @p state. With the
     * adaptive control also each row's state (+4 at its eliminated DoF of
     * @p flags, which hold the integrator's active sets: a row that changed
     * its state in the last step), and the vectors returned, nodal vectors
     * laid out as @p like that the checkpoint carries after u, udot and
     * the flags: the estimator's last acceleration (zero without history)
     * and each row's force in the last step at its eliminated DoF (so that
     * the first step after a resume locates a release as the uninterrupted
     * run does). None with fixed tau.
     */
    std::vector<VectorType>
    save(std::map<std::string, std::string> &state,
         const ContactRows                  &rows,
         VectorType                         &flags,
         const VectorType                   &like) const;

    /// How many vectors save() put into the checkpoint of @p state (older
    /// checkpoints of the adaptive control have no rows' forces).
    unsigned int
    n_checkpoint_vectors(const std::map<std::string, std::string> &state) const;

    /// The inverse of save(), on the mesh the checkpoint's vectors were
    /// transferred to: @p flags and the n_checkpoint_vectors() @p vectors.
    void
    load(const std::map<std::string, std::string> &state,
         const ContactRows                        &rows,
         const VectorType                         &flags,
         const std::vector<VectorType>            &vectors);

  private:
    /// The level tau/2 (adaptive: false at the Minimum time step).
    bool
    halve();

    /// The level 2 tau (false at the Maximum time step).
    bool
    grow();

    /// The next trial takes @p new_tau < the level; the level is kept.
    void
    shorten(const double new_tau);

    // parameters
    double time_step            = 0.0125;
    bool   time_step_adaptation = false;
    bool   is_static            = false;
    bool   adaptive             = false;
    double min_time_step        = 0.;
    double max_time_step        = 0.;
    double tolerance            = 1e-2;
    double end_time             = 0.;
    /// The intervals of stop_at_multiples_of() (false) and of
    /// require_multiples_of() (true).
    std::vector<std::pair<double, bool>> stop_intervals;
    /// What the present trial ends at: a time of stop_at_multiples_of(),
    /// one of require_multiples_of() or End time; nothing of these.
    enum class EndsAt
    {
      level,
      optional_time,
      required_time
    } ends_at = EndsAt::level;
    /// The trial's tau and tau_changed before it was made to end at a time
    /// (restored where an event follows an optional time).
    double uncut_tau         = 0.;
    bool   uncut_tau_changed = false;
    /// Optional times are passed in the present step.
    bool pass_optional_times = false;
    /// n_passed_output_times()
    unsigned int  passed_output_times = 0;
    EventLocation event_location      = EventLocation::onset_and_separation;

    // state
    double tau       = 0.0125;
    double tau_level = 0.0125;
    /// tau changed since the last accepted step
    bool tau_changed = false;
    /// the present step has been shortened to a located event
    bool event_located = false;
    /// the estimates of the trial that judge() accepted allow a larger tau
    bool may_grow = false;
    /// the time the present step starts from
    double          step_start = 0.;
    StepSizeControl estimator;
    /// per row: the contact force of the last accepted step, and whether
    /// that step left the row in the state it started in
    std::vector<double> row_forces;
    std::vector<char>   settled_rows;
  };
} // namespace dyncontact

#endif
