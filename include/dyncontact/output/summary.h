#ifndef dyncontact_output_summary_h
#define dyncontact_output_summary_h

#include <dyncontact/base/statistics.h>

#include <map>
#include <string>

namespace dyncontact
{
  /// What the summary needs besides the statistics table.
  struct SummaryInput
  {
    unsigned int dim = 2;
    /// The energy monitor's tolerance, relative to the energy scale.
    double energy_tolerance = 1e-9;
    bool   is_static        = false;
    /// Wall time of the whole run and of the time loop, in s.
    double wall_time      = 0.;
    double loop_wall_time = 0.;
    /// TimerOutput's sections: wall time (s) and number of calls.
    std::map<std::string, double> section_wall_times;
    std::map<std::string, double> section_calls;
    /// 'Time step control = adaptive': events located, steps repeated
    /// because of the error estimate, step matrices S built.
    bool         adaptive_time_steps = false;
    unsigned int located_events      = 0;
    unsigned int repeated_steps      = 0;
    unsigned int passed_output_times = 0;
    unsigned int step_matrices       = 0;
    /// CG's preconditioner for the last step matrix (static: for A): AMG,
    /// Jacobi or p-multigrid, and for Jacobi the bound of the condition number
    /// of S scaled by its diagonal that 'automatic' decided by (infinite if the
    /// choice was not automatic).
    std::string preconditioner = "AMG";
    /// The MPI ranks and the triangulation that held the mesh
    /// (Mesh/Triangulation): "2 MPI rank(s), distributed triangulation
    /// (p4est)".
    std::string ranks_and_mesh;
    /// whether S is applied without a matrix, and then max_i S_ii / M_ii
    bool   matrix_free     = false;
    double inertia_ratio   = 1.;
    double condition_bound = 0.;
  };

  /**
   * The summary of a run, from its statistics table alone (so that a test
   * can check every figure against statistics.tsv): the steps and the time,
   * adaptive tau, then @p statistics_lines (each statistic's own:
   * Postprocess::Interface::summary()), the preconditioner and the timer
   * sections. Lines of the form "name: value".
   */
  std::string
  summary_text(const Statistics   &statistics,
               const SummaryInput &input,
               const std::string  &statistics_lines);
} // namespace dyncontact

#endif
