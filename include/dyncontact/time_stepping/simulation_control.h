#ifndef dyncontact_time_stepping_simulation_control_h
#define dyncontact_time_stepping_simulation_control_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <map>
#include <string>

namespace dyncontact
{
  using namespace dealii;

  class TimeStepController;

  /**
   * What happens after an accepted step, decided once when the step is
   * accepted and read by everyone as a value (so that nothing depends on
   * the order in which the simulator and its statistics ask):
   * SimulationControl::advance() decides the output, the checkpoint and
   * the last step, the simulator adds the mesh adaptor's refinement.
   */
  struct StepMoments
  {
    /// An output time is reached (the last step is one): VTU files are
    /// written if they are enabled, sampled statistics are evaluated.
    bool output = false;
    /// A checkpoint is written after this step (the same on all ranks).
    bool checkpoint = false;
    /// The mesh is adapted after this step (never after the last one).
    bool refinement = false;
    /// No step follows.
    bool last = false;
  };

  /**
   * The owner of time (as lethe's SimulationControl): the end time, the
   * step number and the time t_n = t_base + k tau (so that times do not
   * accumulate round-off; t_base is the time at which tau last changed),
   * and the moments of VTU output and of checkpoints (StepMoments). The time
   * step tau is the TimeStepController's: advance() is handed the accepted
   * step's, and the comparisons of times with End time and output times allow
   * round-off of 1e-9 of the controller's present tau. The static problem
   * is one step, to t = 1 (no time: the load factor; the unloaded initial
   * state is at 0).
   */
  class SimulationControl
  {
  public:
    /// The values it is handed by the owners of their subsections:
    /// Time integration/End time (TimeIntegrationParameters),
    /// Output/Output interval (OutputParameters), Checkpointing/Interval in
    /// steps and Interval in minutes (Checkpoints).
    struct Parameters
    {
      double       end_time           = 2.5;
      double       output_interval    = 0.05;
      unsigned int checkpoint_steps   = 0;
      double       checkpoint_minutes = 0.;
    };

    /// @p time_step_controller: the owner of tau (must outlive this).
    SimulationControl(const MPI_Comm            comm,
                      const TimeStepController &time_step_controller);

    /// Takes and checks the parameters; @p is_static: one step, to t = 1.
    void
    parse_parameters(const Parameters &parameters, const bool is_static);

    unsigned int
    get_step() const
    {
      return step;
    }

    double
    get_time() const
    {
      return time;
    }

    double
    get_end_time() const
    {
      return end_time;
    }

    /// Whether another step is to be taken: not once the time is within
    /// end_time_tolerance() of the end time.
    bool
    keep_going() const;

    /// 1e-9 min(tau, End time) (s): a time within it of the end time is at
    /// it (round-off of the steps' sum; for a step longer than the whole run
    /// that of the end time, or a step of 1e9 times the run would end it
    /// before it started).
    double
    end_time_tolerance() const;

    /// The steps of length @p tau that keep_going() takes from the present
    /// time on (the last one may end after the end time).
    double
    steps_to_end(const double tau) const;

    /// After an accepted step of length @p tau: t_{n+1}, counted from t_n if
    /// @p tau_changed since the step before, and the moments of this step
    /// (output, checkpoint, last step; the next output time moves on by one
    /// interval when one is reached, the checkpoint clock restarts).
    StepMoments
    advance(const double tau, const bool tau_changed);

    /// Whether the run is the static problem (one step).
    bool
    is_static_problem() const
    {
      return is_static;
    }

    /// The state a resumed run needs (step, time, next output); load()
    /// refuses an End time that is not after the checkpoint's time.
    void
    save(std::map<std::string, std::string> &state) const;
    void
    load(const std::map<std::string, std::string> &state);

  private:
    const MPI_Comm            comm;
    const TimeStepController &time_step_controller;

    // parameters
    double       end_time           = 2.5;
    double       output_interval    = 0.05;
    unsigned int checkpoint_steps   = 0;
    double       checkpoint_minutes = 0.;
    bool         is_static          = false;

    // state
    unsigned int step        = 0;
    double       time        = 0.;
    double       time_base   = 0.;
    unsigned int steps_since = 0;
    double       next_output = 0.05;
    Timer        since_checkpoint;
  };
} // namespace dyncontact

#endif
