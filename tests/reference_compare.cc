// Reference states: a run writes its states every 0.05 s, a second run
// compares with them (column error_reference, nan between the reference
// times). Compared with itself the error must vanish at every reference
// time; compared with a run at tau/4 on the same mesh it must not, and it
// must stay below the error against the exact solution at those times
// (which holds the spatial error as well).

#include <cmath>

#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
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
}
