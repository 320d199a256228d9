// What a user sees: the summary at the end of a run and in summary.txt, the
// banner, and the progress lines. The bar impact (N-CS++, 40 cells,
// tau = 0.0125 s, T = 2.5 s) is run by the executable; every figure of
// summary.txt is recomputed here from statistics.tsv, and the physical ones
// are held against the exact solution (contact from t = 0.1 s to 2.1 s at
// rho c v0 = 1 Pa, E = 0.05 J/m). Progress lines: one per step with an
// interval of 1e-9 s, none with 0 and none for this short run with the
// default interval. A static problem's summary has no time and no critical
// set, and its figures come from its one solve.

#include <algorithm>
#include <cmath>
#include <regex>

#include "tests.h"

namespace
{
  using testing::check;
  using testing::log;
  using testing::read;

  /// The numbers in the line of @p text that starts with @p key.
  std::vector<double>
  numbers_of(const std::string &text, const std::string &key)
  {
    std::vector<double> values;
    const auto          at = text.find("\n" + key);
    if (at == std::string::npos)
      return values;
    const std::string line =
      text.substr(at + 1 + key.size(), text.find('\n', at + 1) - at - 1);
    const std::regex number(R"([-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?)");
    for (auto it = std::sregex_iterator(line.begin(), line.end(), number);
         it != std::sregex_iterator();
         ++it)
      values.push_back(std::stod(it->str()));
    return values;
  }

  bool
  close(const double a, const double b, const double tolerance = 1e-5)
  {
    return std::abs(a - b) <= tolerance * std::max(std::abs(b), 1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  const double                tau = 0.0125;
  const std::string prm = testing::bar_prm(2, "N-CS++", 40, tau, 2.5) +
                          "set Output directory = summary\n";
  std::ofstream("summary.prm") << prm;
  const auto run = testing::run_program("summary.prm");
  log() << "exit status 0: " << check(run.status == 0) << "\n";

  // the banner
  log() << "banner names the body's DoFs, the obstacle without search, the "
           "elastic material, tau and the steps: "
        << check(
             run.text.find("body 1: 410 DoFs") != std::string::npos &&
             run.text.find("rigid obstacle (no contact search), 5 rows") !=
               std::string::npos &&
             run.text.find("elastic (no viscous form)") != std::string::npos &&
             run.text.find("tau = 0.0125 s, 200 steps") != std::string::npos)
        << "\n";
  log() << "no progress lines in a short run: "
        << check(run.text.find("s/step") == std::string::npos) << "\n";

  const std::string summary = read("summary/summary.txt");
  const auto        s = testing::read_statistics("summary/statistics.tsv");
  log() << "summary.txt printed at the end of the run too: "
        << check(!summary.empty() &&
                 run.text.find(summary) != std::string::npos)
        << "\n";

  const auto time   = s.column("time");
  const auto active = s.column("active_nodes");

  // contact intervals: one, from the first to the last step with active rows
  const auto   interval = numbers_of(summary, "contact intervals:");
  unsigned int first = 0, last = 0;
  for (unsigned int r = 0; r < active.size(); ++r)
    if (active[r] > 0)
      {
        if (first == 0)
          first = r;
        last = r;
      }
  log() << "contact intervals: " << interval[0] << ": ["
        << testing::fmt(interval[1], 4) << ", " << testing::fmt(interval[2], 4)
        << "] s; as in statistics.tsv: "
        << check(interval.size() == 3 && interval[0] == 1 &&
                 close(interval[1], time[first]) &&
                 close(interval[2], time[last]))
        << ", exact [0.1, 2.1] within 3 tau: "
        << check(std::abs(interval[1] - 0.1) <= 3 * tau &&
                 std::abs(interval[2] - 2.1) <= 3 * tau)
        << "\n";

  // peak force and pressure, penetration
  const auto force    = numbers_of(summary, "peak contact force:");
  const auto pressure = numbers_of(summary, "peak contact pressure:");
  const auto forces   = s.column("contact_force");
  const auto peak     = std::max_element(forces.begin(), forces.end());
  log() << "peak contact force " << testing::fmt(force[0], 4)
        << " N/m and pressure " << testing::fmt(pressure[0], 4)
        << " Pa; as in statistics.tsv: "
        << check(close(force[0], *peak) &&
                 close(force[1], time[peak - forces.begin()]) &&
                 close(pressure[0],
                       testing::max_of(s.column("max_contact_pressure"))))
        << ", within 10% of rho c v0 H = 0.1 N/m: "
        << check(std::abs(force[0] / 0.1 - 1.) < 0.1) << "\n";
  const auto penetration = numbers_of(summary, "largest penetration:");
  log() << "largest penetration as in statistics.tsv: "
        << check(close(penetration[0],
                       testing::max_of(s.column("max_penetration"))))
        << "\n";

  // energy
  const auto energy   = numbers_of(summary, "energy E + W_visc:");
  const auto increase = numbers_of(summary, "largest energy increase");
  const auto total    = s.column("energy_total");
  const auto balance  = s.column("energy_balance");
  double     largest  = 0.;
  for (unsigned int r = 1; r < balance.size(); ++r)
    largest = std::max(largest, balance[r] - balance[r - 1]);
  log() << "E + W_visc " << testing::fmt(energy[0], 4) << " J/m at the start "
        << "(exact 0.05), " << testing::fmt(energy[1], 4)
        << " at the end; as in statistics.tsv: "
        << check(close(energy[0], total.front()) &&
                 close(energy[1], total.back()) &&
                 close(energy[2], balance.back()) &&
                 std::abs(increase[0] - largest) < 1e-12 &&
                 close(energy[0], 0.05, 1e-12))
        << ", Theorem 3.2 held: "
        << check(summary.find("Theorem 3.2 held") != std::string::npos) << "\n";

  // the critical set, the error, the iterations
  const auto critical = numbers_of(summary, "sum of meas Gamma*:");
  const auto error    = numbers_of(summary, "error_energy_norm:");
  const auto errors   = s.column("error_energy_norm");
  log() << "sum of meas Gamma* and the energy-norm error (end, maximum) as "
           "in statistics.tsv: "
        << check(close(critical[0], s.column("critical_measure_sum").back()) &&
                 close(error[0], errors.back()) &&
                 close(error[1], time.back()) &&
                 close(error[2], testing::max_of(errors)))
        << "\n";
  const auto iterations = numbers_of(summary, "iterations:");
  auto       sum        = [&](const std::string &name) {
    double x = 0.;
    for (const double v : s.column(name))
      x += v;
    return x;
  };
  log() << "iterations (active-set, projection, CG) as in statistics.tsv: "
        << check(iterations.size() == 3 &&
                 iterations[0] == sum("active_set_iterations") &&
                 iterations[1] == sum("projection_iterations") &&
                 iterations[2] == sum("linear_iterations"))
        << "\n";
  log() << "timer sections listed: "
        << check(summary.find("time step") != std::string::npos &&
                 summary.find("assembly") != std::string::npos)
        << "\n";

  // a static problem (prm/hertz_static.prm on a coarser mesh): no time, no
  // critical set; the active set, contact force and pressure of its solve
  std::ofstream("static.prm")
    << "include " DYNCONTACT_PRM_DIR "/hertz_static.prm\n"
    << "set Output directory = static\n"
    << "subsection Mesh\n  set Initial global refinements = 1\nend\n"
    << "subsection Output\n  set Write vtu = false\nend\n";
  const auto        solve          = testing::run_program("static.prm");
  const std::string static_summary = read("static/summary.txt");
  const auto        st    = testing::read_statistics("static/statistics.tsv");
  const auto        nodes = numbers_of(static_summary, "active nodes:");
  const auto        static_force = numbers_of(static_summary, "contact force:");
  const auto        static_pressure =
    numbers_of(static_summary, "peak contact pressure:");
  log() << "static problem: exit status 0: " << check(solve.status == 0)
        << ", no time and no critical set in the summary: "
        << check(static_summary.find("static problem: one constrained "
                                     "solve") != std::string::npos &&
                 static_summary.find("\ntime:") == std::string::npos &&
                 static_summary.find(" at t = ") == std::string::npos &&
                 static_summary.find("Gamma*") == std::string::npos)
        << ", active nodes and measure, contact force and pressure as in "
           "statistics.tsv: "
        << check(nodes.size() >= 2 && static_force.size() >= 1 &&
                 static_pressure.size() >= 1 &&
                 nodes[0] == st.column("active_nodes").back() &&
                 close(nodes[1], st.column("active_measure").back()) &&
                 close(static_force[0], st.column("contact_force").back()) &&
                 close(static_pressure[0],
                       st.column("max_contact_pressure").back()))
        << ", the force the load on the half model (0.0025 N/m): "
        << check(static_force.size() >= 1 &&
                 close(static_force[0], 0.0025, 1e-6))
        << "\n";

  // progress lines
  std::ofstream("progress.prm")
    << prm << "subsection Output\n  set Progress interval = 1e-9\nend\n";
  const auto   every = testing::run_program("progress.prm");
  unsigned int lines = 0;
  for (std::size_t at = every.text.find("s/step"); at != std::string::npos;
       at             = every.text.find("s/step", at + 1))
    ++lines;
  log() << "Progress interval = 1e-9 s: " << lines
        << " progress lines (one per step), the last at t = 2.5 / 2.5 s: "
        << check(lines == 200 &&
                 every.text.find("step 200, t = 2.5 / 2.5 s (100%), tau = "
                                 "0.0125 s, active 0/5") != std::string::npos)
        << "\n";
  std::ofstream("quiet.prm")
    << prm << "subsection Output\n  set Progress interval = 0\nend\n";
  log() << "Progress interval = 0: none: "
        << check(testing::run_program("quiet.prm").text.find("s/step") ==
                 std::string::npos)
        << "\n";
}
