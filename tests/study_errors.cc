// The study of any input (tools/study.py) where the truth is known: the 2D
// bar impact (10 cells along at level 0, four levels of h and tau together).
// The study knows nothing of the exact solution: it compares each run with
// its finest run, through the states on the finest mesh (prolongated through
// the nested meshes), and estimates the finest run's own error. Its
// estimates must agree with the exact errors that the program computes
// beside (error_energy_norm) and with the exact position of the bar's
// centre of mass: within 20 % in the energy norm (at the end and the
// largest over the sample times, every level), within 10 % in position for
// the runs below the finest (20 % for the finest's own estimate). A study
// run again repeats no run and writes the same CSV; an adaptive input's
// differences obey the triangle inequality with the exact errors; bad input
// is refused.

#include <cmath>
#include <filesystem>
#include <map>

#include "tests.h"

namespace
{

  /// The exact mean displacement of the bar: towards the wall at 1 m/s,
  /// in contact from 0.1 s to 2.1 s (decelerated by rho c v0 H / (rho L H)
  /// = 1 m/s^2), then away at 1 m/s.
  double
  exact_position(const double t)
  {
    if (t <= 0.1)
      return -t;
    if (t <= 2.1)
      return -(0.1 + (t - 0.1) - 0.5 * (t - 0.1) * (t - 0.1));
    return -0.1 + (t - 2.1);
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  std::ofstream("bar.prm") << bar_prm(2, "N-CS++", 10, 0.01, 2.5);
  const std::string command = std::string(DYNCONTACT_PYTHON) + " " +
                              DYNCONTACT_SOURCE_DIR + "/tools/study.py " +
                              "--executable " + DYNCONTACT_EXECUTABLE +
                              " --out study --levels 4 ";
  std::filesystem::remove_all("study");
  const std::string first = run_clean(command + "bar.prm");
  if (first.find("command failed") != std::string::npos)
    std::cout << first;
  const auto rows = read_csv("study/study.csv");
  std::cout << "study: " << rows.size() << " runs" << std::endl;
  const double scale = std::sqrt(0.05); // sqrt of the bar's energy

  for (const auto &row : rows)
    {
      const int         level = std::stoi(row.at("level"));
      const std::string name  = level == 3 ?
                                  "reference-level3" :
                                  "uniform_p1-level" + std::to_string(level);
      const Statistics s = read_statistics("study/" + name + "/statistics.tsv");
      // the exact errors at the study's sample times (every 0.25 s)
      const auto times    = s.column("time"),
                 error    = s.column("error_energy_norm"),
                 position = s.column("mean_displacement_x");
      double energy_max = 0., position_max = 0.;
      for (unsigned int i = 0; i < times.size(); ++i)
        {
          const double t = times[i];
          if (std::abs(t / 0.25 - std::round(t / 0.25)) < 1e-6)
            energy_max = std::max(energy_max, error[i] / scale);
          position_max =
            std::max(position_max, std::abs(position[i] - exact_position(t)));
        }
      const double energy_end = error.back() / scale;
      const auto   ratio = [&](const std::string &column, const double exact) {
        return std::stod(row.at(column)) / exact;
      };
      const double r_end = ratio("estimated_energy_end", energy_end);
      const double r_max = ratio("estimated_energy_max", energy_max);
      const double r_pos = ratio("estimated_position_max", position_max);
      const double position_tolerance = level == 3 ? 0.2 : 0.1;
      std::cout << "level " << level << ": energy norm at the end "
                << (std::abs(r_end - 1) <= 0.2 ? "within" : "NOT within")
                << " 20 %, largest over time "
                << (std::abs(r_max - 1) <= 0.2 ? "within" : "NOT within")
                << " 20 %, position "
                << (std::abs(r_pos - 1) <= position_tolerance ? "within" :
                                                                "NOT within")
                << ' ' << std::round(100 * position_tolerance) << " %"
                << std::endl;
      if (std::abs(r_end - 1) > 0.2 || std::abs(r_max - 1) > 0.2 ||
          std::abs(r_pos - 1) > position_tolerance)
        std::cout << "   estimated/exact: " << r_end << ", " << r_max << ", "
                  << r_pos << std::endl;
    }
  for (const std::string key : {"energy max", "position max"})
    {
      const auto at   = first.find("   " + key + " ");
      const auto line = first.substr(at, first.find('\n', at) - at);
      std::cout << key << ": model '"
                << (line.find("uncorrelated") != std::string::npos ?
                      "uncorrelated" :
                    line.find("one shape") != std::string::npos ? "one shape" :
                                                                  "none")
                << "'" << std::endl;
    }

  // run again: nothing is repeated, the same CSV
  const std::string csv      = read("study/study.csv");
  const std::string second   = run_clean(command + "bar.prm");
  unsigned int      repeated = 0;
  for (auto at = second.find("done before"); at != std::string::npos;
       at      = second.find("done before", at + 1))
    ++repeated;
  std::cout << "run again: " << repeated << " of 4 runs found done, CSV "
            << (read("study/study.csv") == csv ? "identical" : "DIFFERENT")
            << std::endl;

  // an adaptive input (the velocity's Kelly indicator, every 2 steps, one
  // level above the initial mesh): the study runs it beside the uniform
  // runs, its states on adapted meshes (hanging nodes) compared on the
  // uniform finest mesh. The triangle inequality bounds every difference d
  // from the reference by the exact errors of run and reference, |d -
  // e_run| <= e_ref, at the end and for the largest over the samples (1 %
  // of sqrt(E) for the quadrature of the exact solution's kinks).
  std::ofstream("adaptive.prm")
    << bar_prm(2, "N-CS++", 10, 0.01, 2.5)
    << "subsection Mesh refinement\n  set Refinement interval = 2\n"
    << "  set Maximum level = 1\n  set Criteria = kelly velocity\n"
    << "  set Refine fraction = 0.2\n  set Coarsen fraction = 0.3\nend\n";
  std::filesystem::remove_all("adaptive");
  const std::string adaptive =
    run_clean(std::string(DYNCONTACT_PYTHON) + " " + DYNCONTACT_SOURCE_DIR +
              "/tools/study.py --executable " + DYNCONTACT_EXECUTABLE +
              " --out adaptive --levels 3 adaptive.prm");
  if (adaptive.find("command failed") != std::string::npos)
    std::cout << adaptive;
  const auto exact = [&](const std::string &run) {
    // the exact error at the samples (every 0.25 s): at the end, largest
    const Statistics s = read_statistics("adaptive/" + run + "/statistics.tsv");
    const auto times = s.column("time"), error = s.column("error_energy_norm");
    double     largest = 0.;
    for (unsigned int i = 0; i < times.size(); ++i)
      if (std::abs(times[i] / 0.25 - std::round(times[i] / 0.25)) < 1e-6)
        largest = std::max(largest, error[i] / scale);
    return std::make_pair(error.back() / scale, largest);
  };
  const auto reference = exact("reference-level2");
  for (const auto &row : read_csv("adaptive/study.csv"))
    {
      const std::string configuration = row.at("configuration");
      if (configuration != "adaptive" && row.at("level") == "2")
        continue;
      const std::string run =
        (configuration == "adaptive" ? "adaptive" : "uniform_p1") +
        std::string("-level") + row.at("level");
      const auto e   = exact(run);
      const bool end = std::abs(std::stod(row.at("energy_end")) - e.first) <=
                       reference.first + 0.01;
      const bool largest = std::abs(std::stod(row.at("energy_max")) -
                                    e.second) <= reference.second + 0.01;
      std::cout << configuration << " level " << row.at("level")
                << ": |difference - exact error| within the reference's "
                   "exact error at the end: "
                << (end ? "yes" : "NO")
                << ", largest over time: " << (largest ? "yes" : "NO")
                << std::endl;
      if (!end || !largest)
        std::cout << "   difference " << row.at("energy_end") << ", "
                  << row.at("energy_max") << "; exact " << e.first << ", "
                  << e.second << "; reference " << reference.first << ", "
                  << reference.second << std::endl;
    }

  // bad input
  std::ofstream("resume.prm") << "include bar.prm\nsubsection Checkpointing\n"
                                 "  set Resume = true\nend\n";
  for (const auto &[arguments, expected] :
       std::vector<std::pair<std::string, std::string>>{
         {"--levels 1 bar.prm", "--levels must be at least 2"},
         {"--levels 3 resume.prm", "resumes from a checkpoint"},
         {"--levels 3 --samples 7 bar.prm", "no multiple of the Time step"},
         {"--levels 3 missing.prm", "does not exist"}})
    {
      const std::string text =
        run_clean(std::string(DYNCONTACT_PYTHON) + " " + DYNCONTACT_SOURCE_DIR +
                  "/tools/study.py --executable " + DYNCONTACT_EXECUTABLE +
                  " --out bad " + arguments);
      std::cout << arguments << ": "
                << (text.find("command failed") != std::string::npos &&
                        text.find(expected) != std::string::npos ?
                      "refused: " + expected :
                      "NOT refused as expected:\n" + text)
                << std::endl;
    }
}
