// 'Contact solver/Preconditioner = multigrid': the two-level p-multigrid of
// the matrix-free S (Chebyshev on S's diagonal, AMG on S of linear elements
// on the same mesh) against the assembled S with Jacobi.
// - The same run: every statistic but the iteration counts agrees to 1e-7
//   of its scale, with fewer CG iterations (the multigrid is used), on the
//   Hertz drop (two bodies, the ball viscous, hanging nodes) for Q2 with the
//   lumped and Q3 with the consistent mass, the 3D bar with Q2, and the 2D bar
//   with Q2 on an adapted mesh (the linear level follows every new mesh).
// - It does what it is for: on the 2D bar with Q2 at tau = 8 h/c (h the
//   cell size), where S is far from its mass, it needs at most a third of
//   Jacobi's CG iterations (measured: 161 against 665 at 16 cells along,
//   136 against 894 at 32), and on the mesh twice as fine at the same
//   tau c/h at most 30 % more iterations (the same number of steps).
// Also on two MPI ranks (step_multigrid.mpirun=2).

#include "hertz_drop.h"

namespace
{
  using namespace testing;

  const std::string jacobi = "subsection Contact solver\n"
                             "  set Preconditioner = Jacobi\nend\n";
  const std::string multigrid =
    "subsection Contact solver\n  set Step matrix = matrix-free\n"
    "  set Preconditioner = multigrid\nend\n";

  /// Runs @p prm with both; returns their comparison.
  SolverComparison
  compare(const std::string &name, const std::string &prm)
  {
    const SolverComparison c =
      compare_solvers(run(tight_steps() + prm + jacobi),
                      run(tight_steps() + prm + multigrid));
    const double tolerance = 1e-7;
    log() << name << ": statistics agree to " << fmt(tolerance, 1) << ": "
          << check(c.difference.first <= tolerance)
          << (c.difference.first <= tolerance ?
                "" :
                " (" + c.difference.second + ": " + fmt(c.difference.first) +
                  ")")
          << ", fewer CG iterations than Jacobi: " << check(c.cg_b < c.cg_a)
          << "\n";
    return c;
  }

  /// The 2D bar with Q2 and @p cells along at tau = 8 h / c (c = 1).
  std::string
  stiff_bar_prm(const unsigned int cells)
  {
    const double tau = 8. / cells;
    return bar_prm(2,
                   "N-CS++",
                   cells,
                   tau,
                   8 * tau,
                   "set Polynomial degree = 2\n"
                   "subsection Scene\n  subsection Bar impact\n"
                   "    set Initial gap = " +
                     std::to_string(1.5 * tau) + "\n  end\nend\n");
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);

  compare("Hertz drop, Q2, lumped mass, hanging nodes", hertz_prm(2, "lumped"));
  compare("Hertz drop, Q3, consistent mass, hanging nodes",
          hertz_prm(3, "consistent"));
  compare("3D bar, Q2",
          bar_prm(3, "N-CS++", 8, 1. / 32., 0.3) +
            "set Polynomial degree = 2\n");
  compare("2D bar, Q2, adaptive (contact zone)",
          bar_prm(2, "N-CS++", 20, 1. / 40., 0.4, q2_contact_zone_prm()));

  const SolverComparison coarse =
    compare("2D bar, Q2, tau = 8 h/c, 16 cells", stiff_bar_prm(16));
  const SolverComparison fine =
    compare("2D bar, Q2, tau = 8 h/c, 32 cells", stiff_bar_prm(32));
  log() << "multigrid CG iterations at most a third of Jacobi's: "
        << check(coarse.cg_b <= coarse.cg_a / 3. && fine.cg_b <= fine.cg_a / 3.)
        << "\n";
  log() << "at twice the cells and the same tau c/h, at most 30 % more "
           "multigrid CG iterations: "
        << check(fine.cg_b <= 1.3 * coarse.cg_b && coarse.cg_b > 0.) << "\n";
}
