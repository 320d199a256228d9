#ifndef dyncontact_postprocess_interface_h
#define dyncontact_postprocess_interface_h

#include <dyncontact/base/plugins.h>
#include <dyncontact/base/statistics.h>
#include <dyncontact/core/simulator_access.h>
#include <dyncontact/output/summary.h>

#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
  class TimerOutput;
} // namespace dealii

namespace dyncontact
{
  namespace Postprocess
  {
    /**
     * One statistic of statistics.tsv (as ASPECT's postprocessors): it
     * declares its columns and fills them after every step. It runs only
     * where it applies (e.g. no error norm without an exact solution). A new
     * statistic is one file with its class and the line
     * DYNCONTACT_REGISTER_POSTPROCESSOR(Class, "name", "what"). Its columns
     * and its lines of summary.txt come where it runs: in the order of
     * Postprocess/List of postprocessors, or of the names for 'all'.
     */
    template <int dim>
    class Interface : public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      virtual void
      parse_parameters(ParameterHandler &)
      {}

      /// Whether the statistic applies to this run (asked once, before the
      /// first step; the scene and the parameters are known then).
      virtual bool
      applies() const
      {
        return true;
      }

      /// The names of its columns.
      virtual std::vector<std::string>
      columns() const = 0;

      /// Whether its columns have values only at some steps, nan between
      /// them (any other statistic that is not finite stops the run).
      virtual bool
      sampled() const
      {
        return false;
      }

      /// Whether its columns are computed after this step; if not, they
      /// get nan (asked only of sampled statistics).
      virtual bool
      due() const
      {
        return true;
      }

      /// Whether it is an error norm: each evaluation is timed as a call of
      /// the section "sampled norms", the other statistics in
      /// "diagnostics".
      virtual bool
      is_norm() const
      {
        return false;
      }

      /// The TimerOutput section of an error norm's evaluations.
      virtual std::string
      timer_section() const
      {
        return "sampled norms";
      }

      /// Appends one value per column for the current step to @p row.
      virtual void
      execute(std::vector<double> &row) = 0;

      /// Its lines of summary.txt ("name: value ..."), from the table of
      /// the whole run @p statistics alone, so that a test can check every
      /// figure against statistics.tsv.
      virtual std::string
      summary(const Statistics &, const SummaryInput &) const
      {
        return "";
      }

      /// Accumulators a resumed run needs (checkpoints).
      virtual void
      save(std::map<std::string, std::string> &) const
      {}
      virtual void
      load(const std::map<std::string, std::string> &)
      {}
    };



    /// The summary line of an error column @p name: its last value and its
    /// largest, with their times.
    std::string
    error_summary(const Statistics &statistics, const std::string &name);



    /**
     * The statistics of Postprocess/List of postprocessors (all that apply,
     * by default), run in the order of the list (for 'all': of their
     * names, as ASPECT runs its postprocessors in the listed order): the
     * table
     * (step, time, then each postprocessor's columns) and statistics.tsv,
     * written and flushed after every step on rank 0.
     */
    template <int dim>
    class Manager : public SimulatorAccess<dim>
    {
    public:
      /// Declares the parameters of every postprocessor.
      static void
      declare_parameters(ParameterHandler &prm);

      /// Creates every postprocessor and reads its parameters.
      void
      parse_parameters(ParameterHandler &prm);

      /// Gives every postprocessor the simulator, keeps those that apply
      /// and sets the columns.
      void
      initialize_simulator(const Simulator<dim> &simulator) override;

      /// Starts statistics.tsv with its header and the rows so far.
      void
      open_file(const std::string &file);

      /// One row for the current step: step, time, every postprocessor (a
      /// sampled one only if it is due, nan otherwise); the error norms are
      /// computed first, each evaluation timed as a call of the section
      /// "sampled norms", the others in "diagnostics".
      void
      execute(TimerOutput &timer);

      const Statistics &
      get_statistics() const
      {
        return statistics;
      }

      /// Whether column @p c of the statistics has values only at some
      /// steps (nan between them).
      bool
      is_sampled(const unsigned int c) const
      {
        return sampled_columns[c];
      }

      /// Stops the run with a message naming the statistic if a value of
      /// the last row is not finite (nan in a sampled column marks a step
      /// without a value).
      void
      check_last_row() const;

      /// The lines every statistic contributes to summary.txt, in the order
      /// the statistics run.
      std::string
      summary(const SummaryInput &input) const;

      /// The column names, the rows so far and every postprocessor's
      /// accumulators (load() refuses rows of other columns).
      void
      save(std::map<std::string, std::string> &state) const;
      void
      load(const std::map<std::string, std::string> &state);

    private:
      std::vector<std::unique_ptr<Interface<dim>>> postprocessors;
      /// The name of each postprocessor if 'List of postprocessors' named
      /// it (it must apply), "" if it is there by 'all'.
      std::vector<std::string> listed;
      Statistics               statistics;
      std::vector<bool>        sampled_columns;
      std::ofstream            file;
      std::string              file_name;
    };
  } // namespace Postprocess

  extern template class PluginRegistry<Postprocess::Interface>;
} // namespace dyncontact

/// Registers a postprocessor (the statistics run in the order of Postprocess/
/// List of postprocessors, or of their names).
#define DYNCONTACT_REGISTER_POSTPROCESSOR(classname, name, description) \
  DYNCONTACT_REGISTER_PLUGIN(dyncontact::Postprocess::Interface,        \
                             classname,                                 \
                             name,                                      \
                             description)

#endif
