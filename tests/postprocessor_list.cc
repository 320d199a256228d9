// Postprocess/List of postprocessors switches statistics on and off: by
// default ('all') every statistic that applies has its columns, in the
// order of the statistics' names; a list gives exactly the columns of the
// named statistics in the order of the list, with the same values as the
// default run, and their lines of summary.txt in the same order; an unknown
// name, a name listed twice and a named statistic that does not apply to
// the run are refused with a message naming them.

#include "tests.h"

namespace
{
  std::string
  joined(const std::vector<std::string> &columns)
  {
    std::string text;
    for (const auto &c : columns)
      text += (text.empty() ? "" : " ") + c;
    return text;
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  auto prm = [](const std::string &list) {
    return bar_prm(2, "N-CS++", 10, 0.05, 1.5) +
           "set Output directory = results-list\n" +
           (list.empty() ? std::string() :
                           "subsection Postprocess\n"
                           "  set List of postprocessors = " +
                             list + "\nend\n");
  };

  const Statistics all = run(prm(""));
  log() << "default: " << all.columns.size() << " columns, "
        << check(all.has_column("error_energy_norm") &&
                 all.has_column("momentum_x") && all.has_column("active_nodes"))
        << "\n  " << joined(all.columns) << "\n";
  const std::string all_summary = read("results-list/summary.txt");

  // the lines of summary.txt that start with one of @p starts, in order
  const auto lines_of = [](const std::string              &summary,
                           const std::vector<std::string> &starts) {
    std::vector<std::string> found;
    std::istringstream       in(summary);
    for (std::string line; std::getline(in, line);)
      for (const auto &start : starts)
        if (line.rfind(start, 0) == 0)
          found.push_back(start);
    return found;
  };
  const std::vector<std::string> firsts = {"peak contact force",
                                           "energy E + W_visc",
                                           "sum of meas Gamma*",
                                           "error_energy_norm",
                                           "iterations"};
  log() << "  summary.txt in the order of the names (contact, critical set, "
           "energy, error energy norm, solver effort): "
        << check(lines_of(all_summary, firsts) ==
                 std::vector<std::string>{"peak contact force",
                                          "sum of meas Gamma*",
                                          "energy E + W_visc",
                                          "error_energy_norm",
                                          "iterations"})
        << "\n";

  for (const std::string list : {"contact, energy", "energy, contact"})
    {
      const Statistics some = run(prm(list));
      log() << list << ": " << joined(some.columns) << "\n";
      bool same = some.rows.size() == all.rows.size();
      for (unsigned int c = 2; same && c < some.columns.size(); ++c)
        same = some.column(some.columns[c]) == all.column(some.columns[c]);
      log() << "  the same values as in the default run: " << check(same)
            << "\n";
      const bool contact_first = list == "contact, energy";
      log() << "  summary.txt has the lines of the two in the list's order: "
            << check(lines_of(read("results-list/summary.txt"), firsts) ==
                     (contact_first ?
                        std::vector<std::string>{"peak contact force",
                                                 "energy E + W_visc"} :
                        std::vector<std::string>{"energy E + W_visc",
                                                 "peak contact force"}))
            << "\n";
    }

  const std::string with_all = error_of(prm("all, energy"));
  log() << "'all' beside a name is refused: "
        << check(with_all.find("'all' stands alone") != std::string::npos)
        << "\n";

  const std::string twice = error_of(prm("energy, contact, energy"));
  log() << "a name listed twice is refused, naming it: "
        << check(twice.find("List of postprocessors") != std::string::npos &&
                 twice.find("'energy' twice") != std::string::npos)
        << "\n";

  const std::string unknown = error_of(prm("energie"));
  log() << "an unknown name is refused, naming the entry: "
        << check(unknown.find("List of postprocessors") != std::string::npos &&
                 unknown.find("energie") != std::string::npos)
        << "\n";

  const std::string not_applying = error_of(prm("energy, mesh transfer"));
  log() << "a statistic that does not apply (mesh transfer on a fixed mesh) "
           "is refused, naming it: "
        << check(not_applying.find("'mesh transfer'") != std::string::npos &&
                 not_applying.find("does not apply") != std::string::npos)
        << "\n";
}
