#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/base/input_checks.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <algorithm>
#include <cerrno>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dyncontact
{
  template class PluginRegistry<Postprocess::Interface>;

  namespace Postprocess
  {
    std::string
    error_summary(const Statistics &s, const std::string &name)
    {
      const auto         time = s.column("time");
      const auto         e    = s.column(name);
      const unsigned int last = s.row_of_last_value(name);
      const unsigned int max  = s.row_of_largest(name);
      std::ostringstream out;
      out << std::setprecision(6) << name << ": " << e[last]
          << " at t = " << time[last] << " s (the last value), " << e[max]
          << " at most (t = " << time[max] << " s)\n";
      return out.str();
    }



    template <int dim>
    void
    Manager<dim>::declare_parameters(ParameterHandler &prm)
    {
      std::string documentation;
      for (const auto &info : PluginRegistry<Interface>::plugins())
        documentation += (documentation.empty() ? "" : "; ") + info.name +
                         ": " + info.description;
      prm.enter_subsection("Postprocess");
      prm.declare_entry(
        "List of postprocessors",
        "all",
        Patterns::MultipleSelection("all|" +
                                    PluginRegistry<Interface>::names("|")),
        "The statistics (groups of columns of statistics.tsv) to compute, "
        "comma-separated, or 'all': every one that applies to the run. They "
        "run in the order of the list ('all': in the order of their names), "
        "and their columns in statistics.tsv and their lines in summary.txt "
        "come in that order. A statistic named here must apply (e.g. 'error "
        "energy norm' needs a scene with an exact solution). " +
          documentation + ".");
      prm.leave_subsection();
      PluginRegistry<Interface>::declare_parameters(prm);
    }



    template <int dim>
    void
    Manager<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Postprocess");
      const std::string list   = prm.get("List of postprocessors");
      const auto        chosen = Utilities::split_string_list(list);
      prm.leave_subsection();
      postprocessors.clear();
      listed.clear();
      // in the order of the list (ASPECT's way), all of them in the order of
      // their names
      AssertThrow(chosen.size() == 1 ||
                    std::find(chosen.begin(), chosen.end(), "all") ==
                      chosen.end(),
                  ExcMessage("Postprocess/List of postprocessors: 'all' "
                             "stands alone (it names every statistic that "
                             "applies); got '" +
                             list + "'."));
      if (chosen.size() == 1 && chosen[0] == "all")
        for (const auto &info : PluginRegistry<Interface>::plugins())
          {
            postprocessors.push_back(info.template create<dim>());
            listed.emplace_back();
          }
      else
        for (const auto &name : chosen)
          {
            AssertThrow(
              std::find(listed.begin(), listed.end(), name) == listed.end(),
              ExcMessage("Postprocess/List of postprocessors names '" + name +
                         "' twice."));
            const auto *info = PluginRegistry<Interface>::find(name);
            Assert(info != nullptr, ExcInternalError()); // (the pattern)
            postprocessors.push_back(info->template create<dim>());
            listed.push_back(name);
          }
      for (auto &postprocessor : postprocessors)
        postprocessor->parse_parameters(prm);
    }



    template <int dim>
    std::string
    Manager<dim>::summary(const SummaryInput &input) const
    {
      std::string lines;
      if (statistics.rows.empty())
        return lines;
      for (const auto &postprocessor : postprocessors)
        lines += postprocessor->summary(statistics, input);
      return lines;
    }



    template <int dim>
    void
    Manager<dim>::initialize_simulator(const Simulator<dim> &simulator)
    {
      SimulatorAccess<dim>::initialize_simulator(simulator);
      std::vector<std::unique_ptr<Interface<dim>>> applicable;
      statistics.columns = {"step", "time"};
      sampled_columns    = {false, false};
      for (unsigned int k = 0; k < postprocessors.size(); ++k)
        {
          auto &postprocessor = postprocessors[k];
          postprocessor->initialize_simulator(simulator);
          // one that is named in the list must apply
          AssertThrow(listed[k].empty() || postprocessor->applies(),
                      ExcMessage("Postprocess/List of postprocessors names '" +
                                 listed[k] +
                                 "', which does not apply to this run (see "
                                 "its description in the parameter "
                                 "documentation, e.g. dyncontact "
                                 "--help)."));
          if (postprocessor->applies())
            {
              for (const auto &column : postprocessor->columns())
                {
                  statistics.columns.push_back(column);
                  sampled_columns.push_back(postprocessor->sampled());
                }
              applicable.push_back(std::move(postprocessor));
            }
        }
      postprocessors = std::move(applicable);
    }



    template <int dim>
    void
    Manager<dim>::open_file(const std::string &name)
    {
      file_name = name;
      std::string failure;
      if (Utilities::MPI::this_mpi_process(this->get_mpi_communicator()) == 0)
        {
          errno = 0;
          file.open(name);
          statistics.write_header(file);
          for (const auto &row : statistics.rows)
            statistics.write_row(file, row);
          file.flush();
          if (!file.good())
            failure = write_failure(name);
        }
      stop_with_message_of_rank_0(failure, this->get_mpi_communicator());
    }



    template <int dim>
    void
    Manager<dim>::execute(TimerOutput &timer)
    {
      std::vector<double> row = {double(this->get_control().get_step()),
                                 this->get_control().get_time()};
      // the error norms first, each evaluation timed apart; a sampled
      // statistic that is not due gets nan; the columns keep their order
      std::vector<std::vector<double>> values(postprocessors.size());
      const auto                       skipped = [&](const unsigned int k) {
        if (!postprocessors[k]->sampled() || postprocessors[k]->due())
          return false;
        values[k].assign(postprocessors[k]->columns().size(),
                         std::numeric_limits<double>::quiet_NaN());
        return true;
      };
      for (unsigned int k = 0; k < postprocessors.size(); ++k)
        if (postprocessors[k]->is_norm() && !skipped(k))
          {
            TimerOutput::Scope t(timer, postprocessors[k]->timer_section());
            postprocessors[k]->execute(values[k]);
          }
      {
        TimerOutput::Scope t(timer, "diagnostics");
        for (unsigned int k = 0; k < postprocessors.size(); ++k)
          if (!postprocessors[k]->is_norm() && !skipped(k))
            postprocessors[k]->execute(values[k]);
      }
      for (const auto &v : values)
        row.insert(row.end(), v.begin(), v.end());
      Assert(row.size() == statistics.columns.size(), ExcInternalError());
      statistics.rows.push_back(row);
      // (a statistics file that cannot be written stops the run on every
      // rank)
      std::string failure;
      if (file.is_open())
        {
          errno = 0;
          statistics.write_row(file, row);
          file.flush();
          if (!file.good())
            failure = write_failure(file_name);
        }
      stop_with_message_of_rank_0(failure, this->get_mpi_communicator());
    }



    template <int dim>
    void
    Manager<dim>::check_last_row() const
    {
      const std::vector<double> &row = statistics.rows.back();
      for (unsigned int c = 0; c < statistics.columns.size(); ++c)
        AssertThrow(
          std::isfinite(row[c]) || (is_sampled(c) && std::isnan(row[c])),
          ExcMessage("step " + std::to_string(this->get_control().get_step()) +
                     " (t = " + format_number(this->get_control().get_time()) +
                     " s): the statistic '" + statistics.columns[c] + "' is " +
                     format_number(row[c]) +
                     ". Check the input for values far outside physical "
                     "ranges (lengths, moduli, densities)."));
    }



    template <int dim>
    void
    Manager<dim>::save(std::map<std::string, std::string> &state) const
    {
      std::ostringstream rows;
      rows << std::setprecision(17) << statistics.rows.size() << "\n";
      for (const auto &row : statistics.rows)
        {
          for (unsigned int c = 0; c < row.size(); ++c)
            rows << (c ? " " : "") << row[c];
          rows << "\n";
        }
      state["statistics"] = rows.str();
      std::string columns;
      for (const auto &column : statistics.columns)
        columns += (columns.empty() ? "" : " ") + column;
      state["statistics_columns"] = columns;
      for (const auto &postprocessor : postprocessors)
        postprocessor->save(state);
    }



    template <int dim>
    void
    Manager<dim>::load(const std::map<std::string, std::string> &state)
    {
      const std::string damaged =
        "the statistics in the checkpoint are damaged";
      // the rows have no names: they are read only into the same columns
      std::string columns;
      for (const auto &column : statistics.columns)
        columns += (columns.empty() ? "" : " ") + column;
      const auto saved = state.find("statistics_columns");
      AssertThrow(saved != state.end() && saved->second == columns,
                  ExcMessage(
                    "the statistics in the checkpoint have other columns "
                    "than this run's (" +
                    (saved == state.end() ?
                       std::string("a checkpoint of an earlier version of "
                                   "the program, which ordered the columns "
                                   "otherwise") :
                       "'" + saved->second + "' against '" + columns + "'") +
                    "): resume with the Postprocess/List of postprocessors "
                    "of the run that wrote it, or start afresh"));
      std::istringstream rows(state.at("statistics"));
      std::size_t        n_rows = 0;
      rows >> n_rows;
      // every value takes at least two characters: a count beyond that is
      // damage and must not drive an allocation
      AssertThrow(!rows.fail() && n_rows * statistics.columns.size() <=
                                    state.at("statistics").size() / 2,
                  ExcMessage(damaged));
      statistics.rows.assign(n_rows,
                             std::vector<double>(statistics.columns.size()));
      // token by token: std::stod reads nan and inf, operator>> does not
      std::string token;
      for (auto &row : statistics.rows)
        for (double &value : row)
          {
            rows >> token;
            AssertThrow(!rows.fail(), ExcMessage(damaged));
            value = std::stod(token);
          }
      for (auto &postprocessor : postprocessors)
        postprocessor->load(state);
    }

    template class Manager<2>;
    template class Manager<3>;
  } // namespace Postprocess
} // namespace dyncontact
