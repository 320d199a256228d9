#include <deal.II/base/parameter_handler.h>

#include <dyncontact/output/output_parameters.h>

namespace dyncontact
{
  using namespace dealii;

  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Output interval",
                      "0.05",
                      Patterns::Double(0.),
                      "Time between two output times, in s (>= 0; 0: every "
                      "step): VTU files are written then (if Write vtu), and "
                      "the energy-norm error is integrated then (with "
                      "Postprocess/Error energy norm/Interval = output times). "
                      "statistics.tsv gets every step. Fixed time steps: at "
                      "the first step at or after each output time; adaptive "
                      "ones end at the output times, except one nearer than "
                      "the Minimum time step to a step's start or followed "
                      "within a step by a contact event (then as with fixed "
                      "steps).");
    prm.declare_entry("Progress interval",
                      "10",
                      Patterns::Double(0.),
                      "Wall time between two progress lines of a long run, "
                      "in s (each line: step, t / T, tau, active rows, "
                      "active-set and CG iterations of the last step, wall "
                      "time per step, estimated time to the end). A run "
                      "shorter than this prints none; 0: no progress lines.");
    prm.declare_entry("Write vtu",
                      "true",
                      Patterns::Bool(),
                      "Whether to write VTU/PVTU files and solution.pvd. "
                      "false skips all output work.");
    prm.declare_entry("Compression",
                      "fast",
                      Patterns::Selection("none|fast|best"),
                      "zlib compression of the VTU files: none (largest "
                      "files, quickest to write), fast (zlib's fastest "
                      "level: files about as small, written several times "
                      "faster than with best) or best (smallest files).");
    prm.declare_entry(
      "Cells per piece",
      "65536",
      Patterns::Integer(1),
      "Each rank writes its cells as VTU pieces (one .vtu file each, all "
      "listed in the .pvtu record) of at most this many cells. A write needs "
      "memory for one piece's patches and compressed data beyond the run's "
      "own: about 1.2 kB per cell in 3D with linear elements, 80 MB per "
      "piece by default.");
    prm.leave_subsection();
  }



  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    output_interval   = prm.get_double("Output interval");
    progress_interval = prm.get_double("Progress interval");
    write_vtu         = prm.get_bool("Write vtu");
    compression       = prm.get("Compression");
    cells_per_piece   = prm.get_integer("Cells per piece");
    prm.leave_subsection();
  }
} // namespace dyncontact
