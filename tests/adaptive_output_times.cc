// Output times under adaptive tau: its steps end at every multiple of
// Output/Output interval (as they end at the reference times and at End
// time), so the VTU files (solution.pvd's times) and the energy-norm error
// sampled at the output times are at exactly those times; but an output
// time followed within a step by a contact event is passed (the event is
// located, and the output is made at the step that ends there). With a fixed
// tau that does not divide the interval, an output is written at the first step
// at or after each output time, at that step's own time (which
// solution.pvd records).

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "tests.h"

namespace
{
  /// The times of solution.pvd in @p directory.
  std::vector<double>
  pvd_times(const std::string &directory)
  {
    std::ifstream      in(directory + "/solution.pvd");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string   all = text.str();
    const std::regex    timestep("timestep=\"([^\"]*)\"");
    std::vector<double> times;
    for (auto it = std::sregex_iterator(all.begin(), all.end(), timestep);
         it != std::sregex_iterator();
         ++it)
      times.push_back(std::stod((*it)[1]));
    return times;
  }

  /// The times of the rows with a sampled (finite) energy-norm error.
  std::vector<double>
  sampled_times(const dyncontact::Statistics &s)
  {
    const auto          time = s.column("time");
    const auto          norm = s.column("error_energy_norm");
    std::vector<double> times;
    for (std::size_t k = 0; k < time.size(); ++k)
      if (std::isfinite(norm[k]))
        times.push_back(time[k]);
    return times;
  }

  /// Whether @p a and @p b hold the same times (to 1e-9 s: the files print
  /// them with different digits).
  bool
  same_times(const std::vector<double> &a, const std::vector<double> &b)
  {
    if (a.size() != b.size())
      return false;
    for (std::size_t k = 0; k < a.size(); ++k)
      if (std::abs(a[k] - b[k]) > 1e-9)
        return false;
    return true;
  }

  /// The times of @p times that are not 0, @p end or a multiple of
  /// @p interval (to 1e-9 of it).
  std::vector<double>
  off_the_grid(const std::vector<double> &times,
               const double               interval,
               const double               end)
  {
    std::vector<double> off;
    for (const double t : times)
      if (std::abs(t / interval - std::round(t / interval)) > 1e-9 &&
          std::abs(t - end) > 1e-12)
        off.push_back(t);
    return off;
  }

  /// Whether the k-th time of @p times lies in [k interval, k interval +
  /// tau) (the last may be End time).
  bool
  first_step_after(const std::vector<double> &times,
                   const double               interval,
                   const double               tau)
  {
    for (std::size_t k = 0; k + 1 < times.size(); ++k)
      if (times[k] < k * interval - 1e-12 ||
          times[k] >= k * interval + tau - 1e-12)
        return false;
    return true;
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  const double interval = 0.03, end = 0.5;
  // 0, 0.03, ..., 0.48 and End time
  const std::size_t expected = 18;
  const auto        prm      = [&](const std::string &control) {
    return bar_prm(2, "N-CS++", 20, 0.025, end) +
           "subsection Time integration\n  set Time step control = " + control +
           "\nend\n"
                       "subsection Output\n  set Write vtu = true\n"
                       "  set Output interval = 0.03\nend\n"
                       "subsection Postprocess\n  subsection Error energy norm\n"
                       "    set Interval = output times\n  end\nend\n"
                       "set Output directory = output-" +
           control + "\n";
  };

  const Statistics adaptive = run(prm("adaptive"));
  const auto       written  = pvd_times("output-adaptive");
  const auto       sampled  = sampled_times(adaptive);
  // the contact starts at g0 / v0 = 0.1 s, within a step after the output
  // time 0.09 s: that output is made at the first step after it, which
  // ends at the located onset
  const auto off = off_the_grid(written, interval, end);
  // (the first step with active rows starts there)
  const auto time   = adaptive.column("time"),
             active = adaptive.column("active_nodes");
  double onset      = -1.;
  for (std::size_t k = 1; k < time.size() && onset < 0.; ++k)
    if (active[k] > 0)
      onset = time[k - 1];
  log() << "adaptive tau, Output interval = 0.03 s, End time = 0.5 s\n"
        << "  solution.pvd: " << written.size() << " times, "
        << check(written.size() == expected) << "; each 0, a multiple of "
        << "0.03 s or End time but " << off.size() << ": "
        << check(off.size() == 1 && std::abs(off[0] - 0.1) < 1e-9)
        << " (0.1 s, the contact onset, written for 0.09 s)\n"
        << "  the first step with active rows starts at 0.1 s (to 1e-9 s): "
        << check(std::abs(onset - 0.1) < 1e-9) << "\n"
        << "  error_energy_norm sampled at " << sampled.size()
        << " rows: " << check(same_times(sampled, written))
        << " (the same times)\n";

  const Statistics fixed         = run(prm("fixed"));
  const auto       fixed_written = pvd_times("output-fixed");
  // (the output for 0.48 s is the last step's, at End time)
  log() << "fixed tau = 0.025 s\n"
        << "  solution.pvd: " << fixed_written.size() << " times, "
        << check(fixed_written.size() == expected - 1)
        << "; the k-th at the first step at or after k * 0.03 s: "
        << check(first_step_after(fixed_written, interval, 0.025))
        << "\n  error_energy_norm sampled at the same times: "
        << check(same_times(sampled_times(fixed), fixed_written)) << "\n";

  // an Output interval below the Minimum time step (tau / 64) does not
  // make the steps that small: the output times are passed
  const auto adaptive_prm = [](const std::string &entries) {
    return bar_prm(2, "N-CS++", 20, 0.025, 0.2) +
           "subsection Time integration\n  set Time step control = "
           "adaptive\n" +
           entries + "end\n";
  };
  const Statistics tiny =
    run(adaptive_prm("") + "subsection Output\n  set Output interval = "
                           "1e-5\nend\nset Output directory = tiny\n");
  log() << "adaptive tau, Output interval = 1e-5 s: the smallest step is "
        << check(min_of(tiny.column("time_step")) >= 0.025 / 64.)
        << " >= Minimum time step\n";

  // a level (0.1 s) above the Output interval (0.05 s): the steps cut to
  // the output times are under the error control as the others
  const auto over = [](const Statistics &s) {
    unsigned int n = 0;
    for (const double eta : s.column("time_step_estimate"))
      n += (eta > 0.002);
    return n;
  };
  const std::string coarse =
    "  set Time step = 0.1\n  set Time step tolerance = 0.002\n";
  const Statistics cut =
    run(adaptive_prm(coarse) + "subsection Output\n  set Output interval = "
                               "0.05\nend\nset Output directory = cut\n");
  const Statistics uncut =
    run(adaptive_prm(coarse) + "subsection Output\n  set Output interval = "
                               "0\nend\nset Output directory = uncut\n");
  log() << "adaptive, Time step 0.1 s, tolerance 0.002: steps above it with "
        << "Output interval 0.05 s: " << over(cut)
        << ", with 0: " << over(uncut) << ": "
        << check(over(cut) <= over(uncut) + 1) << "\n";
}
