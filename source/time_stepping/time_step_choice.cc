// SimulationControl's choice of the time step tau: the trial's tau, the
// retries after a failure or a judgement, the levels (the time, the trial
// loop and the checkpoints are in simulation_control.cc).

#include <deal.II/base/exceptions.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/time_stepping/row_force.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <cmath>

namespace dyncontact
{
  void
  SimulationControl::reset(const std::size_t n_rows)
  {
    estimator.reset();
    row_forces.clear();
    settled_rows.assign(n_rows, 1);
  }



  void
  SimulationControl::stop_at_multiples_of(const double interval)
  {
    if (interval > 0.)
      stop_intervals.emplace_back(interval, false);
  }



  void
  SimulationControl::require_multiples_of(const double       interval,
                                          const std::string &entry)
  {
    AssertThrow(!is_static,
                ExcMessage(entry + ": the static problem has one state and "
                                   "no time; reference states need a "
                                   "dynamic scheme."));
    const double k = interval / time_step;
    AssertThrow(adaptive || (std::round(k) >= 1. &&
                             std::abs(k - std::round(k)) <= 1e-9 * k),
                ExcMessage(entry + " = " + format_number(interval) +
                           " s is not a multiple of Time integration/Time "
                           "step = " +
                           format_number(time_step) +
                           " s: the steps would miss its times. Choose a "
                           "multiple, or 'Time integration/Time step "
                           "control = adaptive' (its steps end at those "
                           "times)."));
    stop_intervals.emplace_back(interval, true);
  }



  void
  SimulationControl::begin_step()
  {
    event_located       = false;
    may_grow            = false;
    pass_optional_times = false;
  }



  double
  SimulationControl::trial_timestep()
  {
    uncut_tau         = tau;
    uncut_tau_changed = tau_changed;
    ends_at           = EndsAt::level;
    if (!adaptive)
      return tau;
    if (time + tau > end_time)
      {
        shorten(end_time - time);
        ends_at = EndsAt::required_time;
      }
    for (const auto &[interval, required] : stop_intervals)
      if (required || !pass_optional_times)
        {
          // the next multiple of the interval after the step's start (a
          // start within 1e-6 intervals of a multiple is at it); a step that
          // ends there up to round-off is not shortened, nor one that would
          // be shorter than the Minimum time step for an optional time
          // (which is then passed)
          const double stop =
            (std::floor(time / interval + 1e-6) + 1.) * interval;
          if (time + tau > stop + 1e-9 * tau &&
              (required || stop - time >= min_time_step))
            {
              shorten(stop - time);
              ends_at =
                required ? EndsAt::required_time : EndsAt::optional_time;
            }
          else if (required && time + tau > stop - 1e-9 * tau)
            ends_at = EndsAt::required_time;
        }
    return tau;
  }



  bool
  SimulationControl::retry_after_failure()
  {
    event_located = false;
    if (adaptive)
      return halve();
    if (!time_step_adaptation || is_static ||
        tau <= time_step / 1024. * (1. + 1e-12))
      return false;
    tau /= 2.;
    tau_level   = tau;
    tau_changed = true;
    return true;
  }



  bool
  SimulationControl::retry_after_judgement(const TrialStep &trial)
  {
    if (!adaptive)
      return false;
    // a contact row that comes into contact or is released inside the step:
    // end the step at the predicted moment (once per step)
    if (!event_located && event_location != EventLocation::none)
      {
        const double fraction =
          StepSizeControl::event_fraction(trial.operators,
                                          trial.row_operator,
                                          trial.active_before,
                                          settled_rows,
                                          row_forces,
                                          trial.u_old,
                                          trial.udot_old,
                                          trial.u,
                                          trial.report,
                                          event_location ==
                                            EventLocation::every_row,
                                          comm);
        // an event in (t_n + tau, t_n + 2 tau), which N-CS++'s projection
        // looks at: after an optional time, that time is passed (the step
        // takes its tau again); a step that ends at a required time or at
        // End time keeps it (the event is located in the step after it);
        // a level step is cut to two steps of half the time to the event,
        // so that the first one's look ahead ends at the event
        const bool   beyond = (fraction >= 1. && fraction < 2.);
        const double theta  = !beyond                  ? fraction :
                              ends_at == EndsAt::level ? fraction / 2. :
                                                         1.;
        if (beyond && ends_at == EndsAt::optional_time)
          {
            pass_optional_times = true;
            ++passed_output_times;
            tau         = uncut_tau;
            tau_changed = uncut_tau_changed;
            return true;
          }
        // not below the Minimum time step
        if (theta < 1. - 1e-2 && theta * tau >= min_time_step)
          {
            shorten(theta * tau);
            event_located = true;
            ++estimator.located_events;
            return true;
          }
      }
    const double eta =
      estimator.estimate(trial.operators, trial.udot_old, trial.udot, tau);
    // a step above the tolerance (but one that ends at a located event) is
    // repeated with the largest level below its tau: tau/2 for a level
    // step; a step cut to end at a given time is shorter than its level
    if (eta > tolerance && !event_located)
      {
        double level = tau_level / 2.;
        while (level >= tau * (1. - 1e-12))
          level /= 2.;
        if (level >= min_time_step * (1. - 1e-12))
          {
            tau_level   = level;
            tau         = level;
            tau_changed = true;
            ++estimator.repeated_steps;
            return true;
          }
      }
    trial.report.error_estimate = eta;
    may_grow =
      estimator.accept(trial.udot_old, trial.udot, tau, eta, tolerance) &&
      !step_is_shortened();
    row_forces.resize(trial.report.active.size());
    settled_rows.resize(trial.report.active.size());
    for (unsigned int p = 0; p < row_forces.size(); ++p)
      {
        row_forces[p]   = row_force(trial.report, p);
        settled_rows[p] = (trial.report.active[p] == trial.active_before[p]);
      }
    return false;
  }



  bool
  SimulationControl::halve()
  {
    if (tau_level / 2. < min_time_step * (1. - 1e-12))
      return false;
    tau_level /= 2.;
    tau         = tau_level;
    tau_changed = true;
    return true;
  }



  bool
  SimulationControl::grow()
  {
    if (2. * tau_level > max_time_step * (1. + 1e-12))
      return false;
    tau_level *= 2.;
    tau         = tau_level;
    tau_changed = true;
    return true;
  }



  void
  SimulationControl::shorten(const double new_tau)
  {
    Assert(new_tau > 0. && new_tau <= tau_level, ExcInternalError());
    tau         = new_tau;
    tau_changed = true;
  }



} // namespace dyncontact
