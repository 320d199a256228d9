#include <deal.II/base/utilities.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/time_stepping/simulation_control.h>
#include <dyncontact/time_stepping/time_step_controller.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dyncontact
{
  SimulationControl::SimulationControl(
    const MPI_Comm            comm,
    const TimeStepController &time_step_controller)
    : comm(comm)
    , time_step_controller(time_step_controller)
  {}



  void
  SimulationControl::parse_parameters(const Parameters &parameters,
                                      const bool        static_problem)
  {
    end_time = parameters.end_time;
    AssertThrow(std::isfinite(end_time) && end_time >= 0.,
                ExcMessage("Time integration/End time must be a finite "
                           "number >= 0 (s); got " +
                           format_number(end_time) + "."));
    if (static_problem)
      // no time: its one state is that of load factor 1 (the unloaded
      // initial state is at 0)
      end_time = 1.;

    output_interval = parameters.output_interval;
    AssertThrow(std::isfinite(output_interval) && output_interval >= 0.,
                ExcMessage("Output/Output interval must be a finite number "
                           ">= 0 (s); got " +
                           format_number(output_interval) + "."));
    checkpoint_steps   = parameters.checkpoint_steps;
    checkpoint_minutes = parameters.checkpoint_minutes;

    is_static   = static_problem;
    step        = 0;
    time        = 0.;
    time_base   = 0.;
    steps_since = 0;
    next_output = output_interval;
  }



  bool
  SimulationControl::keep_going() const
  {
    return is_static ? step < 1 : time < end_time - end_time_tolerance();
  }



  double
  SimulationControl::end_time_tolerance() const
  {
    return 1e-9 * std::min(time_step_controller.get_timestep(), end_time);
  }



  double
  SimulationControl::steps_to_end(const double tau) const
  {
    return std::max(0.,
                    std::ceil((end_time - time - end_time_tolerance()) / tau));
  }



  StepMoments
  SimulationControl::advance(const double tau, const bool tau_changed)
  {
    ++step;
    if (tau_changed)
      {
        time_base   = time;
        steps_since = 0;
      }
    ++steps_since;
    time = is_static ? end_time : time_base + steps_since * tau;

    // the last step is an output too, but the next output time moves on
    // only when it is reached (a resumed run writes the same outputs)
    StepMoments moments;
    moments.last = !keep_going();
    const bool reached =
      time >= next_output - 1e-9 * time_step_controller.get_timestep();
    moments.output = reached || moments.last;
    if (reached)
      next_output += output_interval;
    moments.checkpoint = checkpoint_steps > 0 && step % checkpoint_steps == 0;
    if (checkpoint_minutes > 0.)
      moments.checkpoint =
        moments.checkpoint ||
        Utilities::MPI::broadcast(
          comm, since_checkpoint.wall_time() > 60. * checkpoint_minutes, 0);
    if (moments.checkpoint)
      since_checkpoint.restart();
    return moments;
  }



  void
  SimulationControl::save(std::map<std::string, std::string> &state) const
  {
    auto exact = [](const double x) {
      std::ostringstream s;
      s << std::setprecision(17) << x;
      return s.str();
    };
    state["step"]        = std::to_string(step);
    state["time"]        = exact(time);
    state["next_output"] = exact(next_output);
  }



  void
  SimulationControl::load(const std::map<std::string, std::string> &state)
  {
    const double largest = std::numeric_limits<double>::max();
    step        = checkpoint_number(state, "step", "step number", 0., 4e9);
    time        = checkpoint_number(state, "time", "time t (s)", 0., largest);
    next_output = checkpoint_number(
      state, "next_output", "next output time (s)", 0., largest);
    AssertThrow(end_time > time,
                ExcMessage(
                  "Time integration/End time = " + format_number(end_time) +
                  " s is not after the checkpoint's time t = " +
                  format_number(time) +
                  " s: a resumed run needs a later End time."));
    // t = t_base + k tau from here on
    time_base   = time;
    steps_since = 0;
  }
} // namespace dyncontact
