#ifndef dyncontact_output_run_report_h
#define dyncontact_output_run_report_h

#include <dyncontact/core/simulator_access.h>
#include <dyncontact/output/summary.h>

#include <functional>
#include <string>

namespace dyncontact
{
  /**
   * The run's reports to the user: the banner (what the run uses and leaves
   * out: bodies, contact, material, solver, time steps) and the summary at
   * the end (summary_text() of the statistics, printed and written to
   * summary.txt).
   */
  template <int dim>
  class RunReport : public SimulatorAccess<dim>
  {
  public:
    /// The banner's lines, for the state after the setup.
    std::string
    banner() const;

    /// Prints the summary and writes summary.txt (rank 0); @p wall_time
    /// and @p loop_wall_time: of the run and of its time loop (s);
    /// @p step_matrices: the step matrices S built in the whole run;
    /// @p statistics_lines: the statistics' own lines for the summary's
    /// input (Postprocess::Manager::summary()).
    void
    write_summary(const double       wall_time,
                  const double       loop_wall_time,
                  const unsigned int step_matrices,
                  const std::function<std::string(const SummaryInput &)>
                    &statistics_lines) const;

    /// Removes an earlier run's summary.txt (collective; rank 0 removes),
    /// when this run's own files begin: a summary beside this run's
    /// statistics.tsv is always this run's.
    void
    remove_earlier_summary() const;

    /// Writes summary.txt of a run that failed after its files began: that
    /// it failed, the step and time it had reached, and @p message (rank
    /// 0; not collective, called while the failure unwinds, and never
    /// throws).
    void
    write_failed_summary(const std::string &message) const noexcept;

    /// The name of the summary in the output directory.
    static constexpr const char *file_name = "summary.txt";
  };
} // namespace dyncontact

#endif
