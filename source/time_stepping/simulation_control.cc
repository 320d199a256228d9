#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/time_stepping/simulation_control.h>
#include <dyncontact/time_stepping/time_step_controller.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dyncontact
{
  void
  SimulationControl::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry("End time",
                      "2.5",
                      Patterns::Double(0.),
                      "Final time T, in s (>= 0). If T is not a multiple of "
                      "tau, the last step ends after T. Not used by the "
                      "static scheme (no time: its solution is at t = 1, the "
                      "load factor).");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Output interval",
                      "0.05",
                      Patterns::Double(0.),
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



  SimulationControl::SimulationControl(
    const MPI_Comm            comm,
    const TimeStepController &time_step_controller)
    : comm(comm)
    , time_step_controller(time_step_controller)
  {}



  void
  SimulationControl::parse_parameters(ParameterHandler &prm,
                                      const bool        static_problem)
  {
    prm.enter_subsection("Time integration");
    end_time = prm.get_double("End time");
    prm.leave_subsection();
    AssertThrow(std::isfinite(end_time) && end_time >= 0.,
                ExcMessage("Time integration/End time must be a finite "
                           "number >= 0 (s); got " +
                           format_number(end_time) + "."));
    if (static_problem)
      // no time: its one state is that of load factor 1 (the unloaded
      // initial state is at 0)
      end_time = 1.;

    prm.enter_subsection("Output");
    output_interval = prm.get_double("Output interval");
    prm.leave_subsection();
    AssertThrow(std::isfinite(output_interval) && output_interval >= 0.,
                ExcMessage("Output/Output interval must be a finite number "
                           ">= 0 (s); got " +
                           format_number(output_interval) + "."));

    prm.enter_subsection("Checkpointing");
    checkpoint_steps   = prm.get_integer("Interval in steps");
    checkpoint_minutes = prm.get_double("Interval in minutes");
    prm.leave_subsection();

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
    return is_static ?
             step < 1 :
             time < end_time - 1e-9 * time_step_controller.get_timestep();
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
    // t = t_base + k tau from here on
    time_base   = time;
    steps_since = 0;
  }
} // namespace dyncontact
