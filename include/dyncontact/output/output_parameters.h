#ifndef dyncontact_output_output_parameters_h
#define dyncontact_output_output_parameters_h

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * The one owner of subsection 'Output': it declares and reads every
   * entry, and the components that use them are handed the values: Output
   * interval to SimulationControl (which decides the output times),
   * Progress interval to Progress, Write vtu, Compression and Cells per
   * piece to VtuWriter.
   */
  struct OutputParameters
  {
    /// Output interval, in s of simulated time (0: every step).
    double output_interval = 0.05;
    /// Progress interval, in s of wall time (0: no progress lines).
    double progress_interval = 10.;
    /// Write vtu.
    bool write_vtu = true;
    /// Compression: none, fast or best.
    std::string compression = "fast";
    /// Cells per piece.
    unsigned int cells_per_piece = 65536;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace dyncontact

#endif
