#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/core/simulation_control.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace
  {
    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }
  } // namespace



  void
  SimulationControl::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry("Time step",
                      "0.0125",
                      Patterns::Double(),
                      "Time step tau, in s (> 0).");
    prm.declare_entry("End time",
                      "2.5",
                      Patterns::Double(),
                      "Final time T, in s (>= 0). If T is not a multiple of "
                      "tau, the last step ends after T.");
    prm.declare_entry("Time step adaptation",
                      "false",
                      Patterns::Bool(),
                      "If a step's active-set iteration fails, retry it with "
                      "half the time step (and keep that), down to Time step "
                      "/ 1024; otherwise the run stops with a message.");
    prm.declare_entry(
      "Time step control",
      "fixed",
      Patterns::Selection("fixed|adaptive"),
      "fixed: every step takes Time step. adaptive: tau moves between the "
      "levels Time step * 2^k inside [Minimum time step, Maximum time "
      "step]: a step whose error estimate (see doc/running.md) exceeds "
      "Time step tolerance is repeated with tau/2, tau doubles after two "
      "steps below 1/8 of it; a step that would bring a contact row into "
      "contact (or release one) is shortened to end at the predicted "
      "moment of that event, and the last step ends at End time. Not used "
      "by the static scheme.");
    prm.declare_entry(
      "Event location",
      "onset and separation",
      Patterns::Selection("onset and separation|every row|none"),
      "Adaptive control: which contact events end a step at their "
      "predicted moment. onset and separation: the first row to come into "
      "contact when none is active, and the release when no row stays "
      "active; every row: each row that comes into contact or is released "
      "(in a contact zone that grows node by node nearly every step is "
      "shortened, each with its own step matrix); none.");
    prm.declare_entry("Minimum time step",
                      "0",
                      Patterns::Double(),
                      "Smallest tau of the adaptive control, in s (> 0 and "
                      "<= Time step; 0 means Time step / 64).");
    prm.declare_entry("Maximum time step",
                      "0",
                      Patterns::Double(),
                      "Largest tau of the adaptive control, in s (>= Time "
                      "step; 0 means Time step).");
    prm.declare_entry("Time step tolerance",
                      "0.01",
                      Patterns::Double(),
                      "Adaptive control: the largest error estimate of a "
                      "step that is accepted, relative to the velocity "
                      "scale sqrt(2 E) (dimensionless, > 0).");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Output interval",
                      "0.05",
                      Patterns::Double(),
                      "Time between two output times, in s (>= 0; 0: every "
                      "step): VTU files are written then (if Write vtu), and "
                      "the energy-norm error is integrated then (with "
                      "Postprocess/Error norm interval = output times). "
                      "statistics.tsv gets every step.");
    prm.leave_subsection();

    prm.enter_subsection("Checkpointing");
    prm.declare_entry("Interval in steps",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint every this many steps (0: not by "
                      "steps). Checkpoints go to <Output directory>/"
                      "checkpoints; each is written to a new folder and only "
                      "then marked as the last good one.");
    prm.declare_entry("Interval in minutes",
                      "0",
                      Patterns::Double(0.),
                      "Write a checkpoint when this much wall-clock time (in "
                      "minutes) has passed since the last one (0: not by "
                      "time).");
    prm.leave_subsection();
  }



  SimulationControl::SimulationControl(const MPI_Comm comm)
    : comm(comm)
  {}



  void
  SimulationControl::parse_parameters(ParameterHandler &prm,
                                      const bool        static_problem)
  {
    prm.enter_subsection("Time integration");
    time_step            = prm.get_double("Time step");
    end_time             = prm.get_double("End time");
    time_step_adaptation = prm.get_bool("Time step adaptation");
    adaptive = prm.get("Time step control") == "adaptive" && !static_problem;
    min_time_step = prm.get_double("Minimum time step");
    max_time_step = prm.get_double("Maximum time step");
    tolerance     = prm.get_double("Time step tolerance");
    {
      const std::string location = prm.get("Event location");
      event_location             = location == "none" ? EventLocation::none :
                                   location == "every row" ?
                                                        EventLocation::every_row :
                                                        EventLocation::onset_and_separation;
    }
    prm.leave_subsection();
    AssertThrow(std::isfinite(time_step) && time_step > 0.,
                ExcMessage("Time integration/Time step must be a finite "
                           "number > 0 (s); got " +
                           number(time_step) + "."));
    AssertThrow(std::isfinite(end_time) && end_time >= 0.,
                ExcMessage("Time integration/End time must be a finite "
                           "number >= 0 (s); got " +
                           number(end_time) + "."));
    AssertThrow(end_time / time_step < 1e8,
                ExcMessage("Time integration: End time / Time step = " +
                           number(end_time / time_step) +
                           " steps; at most 1e8 steps are allowed."));
    if (min_time_step == 0.)
      min_time_step = time_step / 64.;
    if (max_time_step == 0.)
      max_time_step = time_step;
    // the adaptive control's parameters matter only with it
    if (adaptive)
      {
        AssertThrow(std::isfinite(min_time_step) && min_time_step > 0. &&
                      min_time_step <= time_step,
                    ExcMessage("Time integration/Minimum time step must be a "
                               "finite number in (0, Time step = " +
                               number(time_step) +
                               "] (s), or 0 for Time step / 64; got " +
                               number(min_time_step) + "."));
        AssertThrow(std::isfinite(max_time_step) && max_time_step >= time_step,
                    ExcMessage("Time integration/Maximum time step must be a "
                               "finite number >= Time step = " +
                               number(time_step) +
                               " (s), or 0 for Time step; got " +
                               number(max_time_step) + "."));
        AssertThrow(std::isfinite(tolerance) && tolerance > 0.,
                    ExcMessage("Time integration/Time step tolerance must be "
                               "a finite number > 0; got " +
                               number(tolerance) + "."));
        AssertThrow(end_time / min_time_step < 1e9,
                    ExcMessage("Time integration: End time / Minimum time "
                               "step = " +
                               number(end_time / min_time_step) +
                               " steps; at most 1e9 are allowed: raise "
                               "Time integration/Minimum time step."));
      }

    prm.enter_subsection("Output");
    output_interval = prm.get_double("Output interval");
    prm.leave_subsection();
    AssertThrow(std::isfinite(output_interval) && output_interval >= 0.,
                ExcMessage("Output/Output interval must be a finite number "
                           ">= 0 (s); got " +
                           number(output_interval) + "."));

    prm.enter_subsection("Checkpointing");
    checkpoint_steps   = prm.get_integer("Interval in steps");
    checkpoint_minutes = prm.get_double("Interval in minutes");
    prm.leave_subsection();

    is_static   = static_problem;
    tau         = time_step;
    tau_level   = time_step;
    step        = 0;
    time        = 0.;
    time_base   = 0.;
    steps_since = 0;
    next_output = output_interval;
  }



  bool
  SimulationControl::keep_going() const
  {
    return is_static ? step < 1 : time < end_time - 1e-9 * tau;
  }



  void
  SimulationControl::advance()
  {
    ++step;
    ++steps_since;
    time = is_static ? end_time : time_base + steps_since * tau;
    if (tau != tau_level)
      {
        // after a shortened step: back to the level
        tau = tau_level;
        restart_count();
      }
  }



  void
  SimulationControl::restart_count()
  {
    time_base   = time;
    steps_since = 0;
  }



  void
  SimulationControl::shorten(const double new_tau)
  {
    Assert(new_tau > 0. && new_tau <= tau_level, ExcInternalError());
    tau = new_tau;
    restart_count();
  }



  void
  SimulationControl::clip_to_end_time()
  {
    if (adaptive && time + tau > end_time)
      shorten(end_time - time);
  }



  bool
  SimulationControl::halve()
  {
    if (tau_level / 2. < min_time_step * (1. - 1e-12))
      return false;
    tau_level /= 2.;
    tau = tau_level;
    restart_count();
    return true;
  }



  bool
  SimulationControl::grow()
  {
    if (2. * tau_level > max_time_step * (1. + 1e-12))
      return false;
    tau_level *= 2.;
    tau = tau_level;
    restart_count();
    return true;
  }



  bool
  SimulationControl::output_due() const
  {
    return time >= next_output - 1e-9 * tau || !keep_going();
  }



  void
  SimulationControl::output_written()
  {
    next_output += output_interval;
  }



  bool
  SimulationControl::checkpoint_due() const
  {
    bool due = checkpoint_steps > 0 && step % checkpoint_steps == 0;
    if (checkpoint_minutes > 0.)
      due = due || Utilities::MPI::broadcast(comm,
                                             since_checkpoint.wall_time() >
                                               60. * checkpoint_minutes,
                                             0);
    return due;
  }



  void
  SimulationControl::checkpoint_written()
  {
    since_checkpoint.restart();
  }



  bool
  SimulationControl::reduce_timestep()
  {
    if (adaptive)
      return halve();
    if (!time_step_adaptation || is_static ||
        tau <= time_step / 1024. * (1. + 1e-12))
      return false;
    tau /= 2.;
    tau_level = tau;
    restart_count();
    return true;
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
    state["tau"]         = exact(tau);
    state["tau_level"]   = exact(tau_level);
    state["next_output"] = exact(next_output);
  }



  void
  SimulationControl::load(const std::map<std::string, std::string> &state)
  {
    step = std::stoul(state.at("step"));
    time = std::stod(state.at("time"));
    tau  = std::stod(state.at("tau"));
    tau_level =
      state.count("tau_level") ? std::stod(state.at("tau_level")) : tau;
    next_output = std::stod(state.at("next_output"));
    // t = t_base + k tau from here on
    time_base   = time;
    steps_since = 0;
  }
} // namespace dyncontact
