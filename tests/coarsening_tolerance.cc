// Mesh refinement/Coarsening tolerance on the 2D bar impact (10 cells
// along, levels 0 to 2 by the velocity's recovery indicator every 2 steps,
// half of the cells flagged for coarsening at each adaptation; not Kelly's,
// whose indicators of the uniform velocity before the impact are round-off
// that the two triangulations break differently). A family of cells
// is coarsened only if what the transfer to its parent removes (its energy
// norm) is at most the tolerance times the energy times the family's share
// of the volume. Checked: no adaptation's removed part has an energy above
// the tolerance times the energy (the statistics' coarsening_removed; the
// energy's change is not bounded by it); a tighter
// tolerance refuses more families and removes less; the wave that carries
// the bar's motion is kept: with the tightest tolerance the exact error
// (energy norm, largest over time) is below that of the same run without
// the limit by more than 10 %; the serial triangulation refuses the same
// families (on one rank); summary.txt names the families kept. Also on 2
// ranks (coarsening_tolerance.mpirun=2).

#include <cmath>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double energy = 0.05; // J/m: the bar's kinetic energy, conserved
  const auto   input  = [](const double tolerance, const bool serial) {
    std::ostringstream s;
    s << "subsection Mesh refinement\n  set Refinement interval = 2\n"
      << "  set Maximum level = 2\n  set Criteria = recovery velocity\n"
      << "  set Refine fraction = 0.2\n  set Coarsen fraction = 0.5\n"
      << "  set Coarsening tolerance = " << tolerance << "\nend\n"
      << (serial ? "subsection Mesh\n  set Triangulation = serial\nend\n" : "");
    return bar_prm(2, "N-CS++", 10, 0.01, 2.5, s.str());
  };

  double       previous_removed = 1e300, error_free = 0.;
  unsigned int previous_refused = 0;
  for (const double tolerance : {0., 1e-3, 1e-4, 1e-5})
    {
      const Statistics s = run(tight_steps() + input(tolerance, false));
      const double     error =
        max_of(s.column("error_energy_norm")) / std::sqrt(energy);
      log() << "Coarsening tolerance = " << tolerance << ":\n";
      if (tolerance == 0.)
        {
          error_free = error;
          log() << "   no columns coarsening_*: "
                << check(std::find(s.columns.begin(),
                                   s.columns.end(),
                                   "coarsening_refused") == s.columns.end())
                << "\n";
          continue;
        }
      const auto   refused = s.column("coarsening_refused");
      const auto   removed = s.column("coarsening_removed");
      double       total = 0., largest = 0.;
      unsigned int n_refused = 0;
      for (unsigned int i = 0; i < removed.size(); ++i)
        {
          total += removed[i];
          largest = std::max(largest, removed[i]);
          n_refused += static_cast<unsigned int>(refused[i]);
        }
      log()
        << "   no adaptation's removed part has more than the tolerance times "
           "the energy: "
        << check(largest <= tolerance * energy * (1. + 1e-6)) << "\n"
        << "   more families refused, less removed than with the "
           "tolerance before: "
        << check(n_refused > previous_refused && total < previous_removed)
        << "\n";
      log() << "   summary.txt names the families kept: "
            << check(read("output-N-CS++-10/summary.txt")
                       .find("coarsening: " + std::to_string(n_refused) +
                             " families kept") != std::string::npos)
            << "\n";
      previous_refused = n_refused;
      previous_removed = total;
      if (tolerance == 1e-5)
        {
          log() << "   exact error (largest over time) below 0.9 times that "
                   "without the limit: "
                << check(error < 0.9 * error_free) << "\n";
          if (n_ranks() > 1)
            continue; // (the serial triangulation runs on one rank)
          const Statistics t = run(tight_steps() + input(tolerance, true));
          double           serial_refused = 0.;
          for (const double r : t.column("coarsening_refused"))
            serial_refused += r;
          log() << "   the serial triangulation refuses as many families: "
                << check(serial_refused == n_refused) << "\n";
        }
    }
}
