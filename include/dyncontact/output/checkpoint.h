#ifndef dyncontact_output_checkpoint_h
#define dyncontact_output_checkpoint_h

#include <deal.II/base/mpi.h>

#include <map>
#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  using namespace dealii;

  /**
   * Checkpoints in <Output directory>/checkpoints: each is written to a new
   * folder step_NNNNNNN (the mesh with u and udot by p4est's save, or on a
   * serial triangulation by SerialMeshFile, written by the simulator into
   * mesh_file(); and state.txt with every component's
   * state as key/value pairs) and only then marked as the last good one by
   * an atomic rename of checkpoints/last, so a crash while writing leaves
   * the previous checkpoint usable; the one before it is kept too. state.txt
   * lists the size and CRC-32 of every other file of the checkpoint and ends
   * with its own checksum; a resumed run verifies them all before it reads
   * anything, so a truncated, damaged or missing file is reported by name
   * instead of being loaded. A resumed
   * run must agree with the checkpoint in its critical parameters (all but
   * End time, Output directory, Output, Checkpointing, Time step adaptation
   * and the solver's iteration limits). A checkpoint that fails the checks
   * is refused with what is wrong, and with the name of the newest other
   * checkpoint beside it that passes the checks and how to resume from it.
   */
  class Checkpoints
  {
  public:
    /// Declares subsection Checkpointing: Resume, Interval in steps,
    /// Interval in minutes (the intervals are SimulationControl's, which
    /// decides the checkpoint steps).
    static void
    declare_parameters(ParameterHandler &prm);

    explicit Checkpoints(const MPI_Comm comm);

    /// Reads subsection Checkpointing and records the critical parameters
    /// of @p prm.
    void
    parse_parameters(ParameterHandler &prm);

    /// The checkpoints are in @p output_directory/checkpoints (Output
    /// directory, handed by its owner, GlobalParameters).
    void
    set_output_directory(const std::string &output_directory);

    bool
    resume() const
    {
      return resume_run;
    }

    /// Checkpointing/Interval in steps (0: not by steps).
    unsigned int
    interval_in_steps() const
    {
      return interval_steps;
    }

    /// Checkpointing/Interval in minutes (0: not by wall time).
    double
    interval_in_minutes() const
    {
      return interval_minutes;
    }

    /// The folder of a new checkpoint for @p step (created, empty).
    std::string
    begin(const unsigned int step) const;

    /// The file (prefix) of the mesh in checkpoint folder @p directory.
    static std::string
    mesh_file(const std::string &directory)
    {
      return directory + "/mesh";
    }

    /// Writes @p state into @p directory and marks the checkpoint as the
    /// last good one (collective).
    void
    finish(const std::string                        &directory,
           const std::map<std::string, std::string> &state) const;

    /// The last good checkpoint's folder; its state after checking the
    /// critical parameters against this run's.
    std::string
    last_directory() const;
    std::map<std::string, std::string>
    read_state(const std::string &directory) const;

    /// Adds a critical parameter that is no prm entry (e.g. the checksum of
    /// an input file), which a resumed run must share with its checkpoint.
    void
    add_critical_parameter(const std::string &name, const std::string &value);

  private:
    /// Checks the files of checkpoint @p directory against the sizes and
    /// checksums in its state.txt: "" if all is well, else what is wrong.
    static std::string
    verify(const std::string &directory);

    /// What to do instead of resuming from the refused checkpoint
    /// @p directory: the newest other checkpoint beside it that verify()
    /// passes, and how to resume from it; or to start afresh. With an
    /// empty @p directory (the file 'last' is missing): the newest of all.
    std::string
    advice_beside(const std::string &directory) const;

    std::string    root;
    const MPI_Comm comm;
    bool           resume_run       = false;
    unsigned int   interval_steps   = 0;
    double         interval_minutes = 0.;
    /// The parameters a resumed run must share with its checkpoint, as text.
    std::string critical_parameters;
  };
} // namespace dyncontact

#endif
