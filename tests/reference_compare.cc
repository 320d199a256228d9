// Reference states: a run writes its states every 0.05 s, a second run
// compares with them (column error_reference, nan between the reference
// times). Compared with itself the error must vanish at every reference
// time; compared with a run at tau/4 on the same mesh it must not, and it
// must stay below the error against the exact solution at those times
// (which holds the spatial error as well). With adaptive tau and an
// interval that no level of tau divides (0.03 s), the steps of both runs
// end at the reference times: every one of them has a value.

#include <cmath>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  const double tau = 0.0125, end = 0.5;
  auto         reference = [&](const std::string &directory, const bool write) {
    return std::string("subsection Reference solution\n") +
           (write ? "  set Write states = true\n" :
                            "  set Compare with states = true\n") +
           "  set Directory = " + directory + "\n  set Interval = 0.05\nend\n";
  };
  run(bar_prm(2, "N-CS++", 40, tau, end, reference("states_tau", true)));
  run(bar_prm(2, "N-CS++", 40, tau / 4, end, reference("states_fine", true)));

  const Statistics self =
    run(bar_prm(2, "N-CS++", 40, tau, end, reference("states_tau", false)));
  const Statistics fine =
    run(bar_prm(2, "N-CS++", 40, tau, end, reference("states_fine", false)));

  const auto   time    = self.column("time");
  unsigned int samples = 0, gaps = 0;
  double       largest_self = 0., smallest_fine = 1e300, margin = 1e300;
  for (unsigned int r = 0; r < time.size(); ++r)
    {
      const double e = self.column("error_reference")[r];
      if (std::isnan(e))
        {
          ++gaps;
          continue;
        }
      ++samples;
      largest_self = std::max(largest_self, e);
      if (time[r] > 0.14)
        {
          const double f = fine.column("error_reference")[r];
          smallest_fine  = std::min(smallest_fine, f);
          margin = std::min(margin, fine.column("error_energy_norm")[r] - f);
        }
    }
  const std::string adaptive =
    "subsection Time integration\n  set Time step control = adaptive\nend\n";
  const auto every_003 = [](const std::string &directory, const bool write) {
    return std::string("subsection Reference solution\n") +
           (write ? "  set Write states = true\n" :
                    "  set Compare with states = true\n") +
           "  set Directory = " + directory + "\n  set Interval = 0.03\nend\n";
  };
  run(bar_prm(
    2, "N-CS++", 40, tau, end, adaptive + every_003("states_ad", true)));
  const Statistics adaptive_self    = run(bar_prm(
    2, "N-CS++", 40, tau, end, adaptive + every_003("states_ad", false)));
  unsigned int     adaptive_samples = 0;
  double           adaptive_largest = 0.;
  for (const double e : adaptive_self.column("error_reference"))
    if (!std::isnan(e))
      {
        ++adaptive_samples;
        adaptive_largest = std::max(adaptive_largest, e);
      }

  log() << "reference times with a value: " << samples
        << " (every 0.05 s from 0 to 0.5 s: 11), rows without: " << gaps << ": "
        << check(samples == 11 && gaps == time.size() - 11) << "\n";
  log() << "compared with itself, largest error " << fmt(largest_self, 1)
        << ": " << check(largest_self < 1e-12) << "\n";
  log()
    << "compared with tau/4, the error after the impact (t >= 0.15 s) is at "
       "least "
    << fmt(smallest_fine, 2)
    << " and below the error against the exact solution: "
    << check(smallest_fine > 1e-4 && margin > 0.) << "\n";
  log() << "adaptive tau, Interval 0.03 s: reference times with a value: "
        << adaptive_samples << " (0 to 0.48 s: 17), largest error against "
        << "itself " << fmt(adaptive_largest, 1) << ": "
        << check(adaptive_samples == 17 && adaptive_largest < 1e-12) << "\n";
}
