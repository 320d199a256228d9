// Mesh refinement/Position tolerance: a coarsening that would move a body is
// refused. A bar vibrating in free flight (initial strain 0.3, nothing to
// hit before T = 3 s), N-CS++, the mesh adapted every 2 steps by Kelly's
// indicator of the velocity, half of the cells coarsened: the coarsening of
// the waves that carry the bar's motion changes its momentum, and its
// centre of mass drifts from x0 + p0 t / m by more than 5e-5 m at T
// (measured 1.3e-4 m). With Position tolerance = 5e-5 m:
// - some families are refused, and the drift at T is at most the tolerance
//   (measured 0), the momentum kept within 1e-9 of m v0 (without: 4e-5);
// - the accepted coarsening's estimates, coarsening_moved summed over the
//   run, are at most the tolerance;
// - it costs few DoFs: the mean at most 1.2 times that without the limit
//   (measured 496 against 485);
// - the summary names the tolerance;
// - a run resumed from a checkpoint at t = 1.5 s gives the same DoFs and
//   coarsening_moved in every row;
// - the serial triangulation (1 rank) gives the same DoFs in every row.
// Also on two MPI ranks (position_tolerance.mpirun=2), with the same output
// but the serial triangulation's line.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const unsigned int cells = 16;
  const double       tau = 1. / cells / 2., v0 = 1., H = 0.1, m = 1. * H,
               tolerance = 5e-5;
  const std::string free_flight =
    scene_entries("Bar impact",
                  "    set Initial gap = 5\n    set Initial strain = 0.3\n");
  const auto prm = [&](const double limit, const double end) {
    std::ostringstream s;
    s << std::setprecision(17)
      << bar_prm(2, "N-CS++", cells, tau, end, free_flight) << tight_steps()
      << "subsection Mesh refinement\n  set Refinement interval = 2\n"
         "  set Maximum level = 2\n  set Criteria = kelly velocity\n"
         "  set Coarsen fraction = 0.5\n  set Position tolerance = "
      << limit << "\nend\nset Output directory = output-" << limit << "\n";
    return s.str();
  };
  // the centre of mass's drift from free flight at T, the momentum's change
  const auto drift = [&](const Statistics &s) {
    const auto x = s.column("mean_displacement_x"),
               y = s.column("mean_displacement_y"), t = s.column("time"),
               px = s.column("momentum_x"), py = s.column("momentum_y");
    const std::size_t n = x.size() - 1;
    return std::make_pair(std::hypot(x[n] - x[0] - px[0] / m * t[n],
                                     y[n] - y[0] - py[0] / m * t[n]),
                          std::hypot(px[n] - px[0], py[n] - py[0]));
  };

  const Statistics free       = run(prm(0., 3.));
  const auto [d_free, p_free] = drift(free);
  log() << "without a limit, the coarsening moves the bar by more than "
        << tolerance << " m at T: " << check(d_free > tolerance) << "\n";

  const Statistics limited          = run(prm(tolerance, 3.));
  const auto [d_limited, p_limited] = drift(limited);
  double moved = 0., refused = 0.;
  for (const double x : limited.column("coarsening_moved"))
    moved += x;
  for (const double x : limited.column("coarsening_refused"))
    refused += x;
  log() << "Position tolerance = " << tolerance << " m:\n"
        << "  some families refused: " << check(refused > 0.)
        << "\n  the drift at T at most the tolerance: "
        << check(d_limited <= tolerance)
        << "\n  the momentum kept within 1e-9 of m v0 (without the limit "
        << (p_free > 1e-6 * m * v0 ? "more than 1e-6" : "less")
        << "): " << check(p_limited <= 1e-9 * m * v0)
        << "\n  the accepted coarsening's estimates, summed, at most the "
           "tolerance: "
        << check(moved <= tolerance) << "\n  mean DoFs at most 1.2 times "
        << "those without the limit: "
        << check(mean_of(limited.column("dofs")) <=
                 1.2 * mean_of(free.column("dofs")))
        << "\n  summary.txt names it: "
        << check(read("output-" + fmt(tolerance, 17) + "/summary.txt")
                   .find("Position tolerance = 5e-05 m") != std::string::npos)
        << "\n";

  // resumed from a checkpoint at t = 1.5 s
  const auto split = [&](const double end, const bool resume) {
    return prm(tolerance, end) + "set Output directory = resumed\n" +
           checkpointing(48, resume);
  };
  run(split(1.5, false));
  const Statistics resumed = run(split(3., true));
  bool             same    = resumed.column("dofs") == limited.column("dofs");
  for (unsigned int i = 0; same && i < limited.column("dofs").size(); ++i)
    same = std::abs(resumed.column("coarsening_moved")[i] -
                    limited.column("coarsening_moved")[i]) <= 1e-12;
  log() << "resumed from t = 1.5 s: the same DoFs and coarsening_moved in "
           "every row: "
        << check(same) << "\n";

  // (the serial triangulation on one rank)
  if (n_ranks() > 1)
    return 0;
  const Statistics serial =
    run(prm(tolerance, 3.) + "subsection Mesh\n  set Triangulation = serial\n"
                             "end\nset Output directory = serial\n");
  log() << "the serial triangulation: the same DoFs in every row: "
        << check(serial.column("dofs") == limited.column("dofs")) << "\n";
}
