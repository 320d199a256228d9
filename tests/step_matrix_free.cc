// 'Contact solver/Step matrix = matrix-free' against 'assembled': S = M +
// tau^2/4 A + tau/2 B applied cell by cell (with Jacobi on its diagonal,
// computed without a matrix, equal to the assembled S's) gives the same run
// as the assembled S with Jacobi: every statistic but the iteration counts
// agrees to 1e-7 of its scale (statistics_difference()), and CG needs as
// many iterations in all within 5 % (the iterates differ by round-off only,
// which can move a stop by one iteration), on
// - the viscous 2D bar (uniform mesh, Q1, lumped mass) for the three
//   schemes;
// - the Hertz drop (two bodies, the ball viscous, hanging nodes where the
//   contact zone is refined) for p = 1, 2, 3, with the lumped and the
//   consistent mass (the assembled S then with 'Preconditioner = Jacobi',
//   not the AMG that 'automatic' takes), and for p = 2 with Time
//   integration/Numerical dissipation = 0.1 (S = M + 0.3 tau^2 A + tau/2 B);
// - the 3D bar with Q2 elements;
// - the 2D bar with adaptive time steps (tau levels cached, steps shortened
//   to contact events, each with its own S);
// - an adaptive mesh: the bar refined by the contact zone criterion, which
//   marks the same cells for both (Kelly's indicators of a uniform velocity
//   before the impact are round-off, and refine differently for the two).
// Also on two MPI ranks (step_matrix_free.mpirun=2).

#include "hertz_drop.h"

namespace
{
  using namespace testing;

  /// Compares the run of @p prm with both step matrices.
  void
  compare(const std::string &name, const std::string &prm)
  {
    const std::string jacobi    = "subsection Contact solver\n"
                                  "  set Preconditioner = Jacobi\nend\n";
    const Statistics  assembled = run(tight_steps() + prm + jacobi);
    const Statistics  matrix_free =
      run(tight_steps() + prm + jacobi +
          "subsection Contact solver\n  set Step matrix = matrix-free\nend\n");
    const SolverComparison c          = compare_solvers(assembled, matrix_free);
    const auto            &difference = c.difference;
    const double           tolerance  = 1e-7;
    const double           sum_a = c.cg_a, sum_b = c.cg_b;
    log() << name << ": statistics agree to " << fmt(tolerance, 1) << ": "
          << check(difference.first <= tolerance)
          << (difference.first <= tolerance ?
                "" :
                " (" + difference.second + ": " + fmt(difference.first) + ")")
          << ", CG iterations within 5 %: "
          << check(std::abs(sum_b - sum_a) <= 0.05 * sum_a && sum_a > 0.)
          << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);

  const std::string viscous = "subsection Material\n"
                              "  set Poisson's ratio = 0.3\n"
                              "  set Viscous shear modulus = 0.002\n"
                              "  set Viscous Lame parameter = 0.001\nend\n";
  // (tau = 1/81 s: with 1/80 s the bar touches the wall exactly at the end
  // of step 8, where round-off decides whether N-CS's predictor is active)
  for (const std::string scheme : {"N-CI", "N-CS", "N-CS++"})
    compare("2D bar, Q1, viscous, " + scheme,
            bar_prm(2, scheme, 40, 1. / 81., 0.5, viscous));

  for (const unsigned int degree : {1, 2, 3})
    for (const std::string mass : {"lumped", "consistent"})
      compare("Hertz drop, Q" + std::to_string(degree) + ", " + mass +
                " mass, hanging nodes",
              hertz_prm(degree, mass));

  compare("Hertz drop, Q2, lumped mass, hanging nodes, numerical dissipation "
          "0.1",
          hertz_prm(2, "lumped") + "subsection Time integration\n"
                                   "  set Numerical dissipation = 0.1\nend\n");

  compare("3D bar, Q2",
          bar_prm(3, "N-CS++", 8, 1. / 32., 0.3) +
            "set Polynomial degree = 2\n");

  compare("2D bar, Q2, adaptive time steps",
          bar_prm(2,
                  "N-CS++",
                  20,
                  1. / 40.,
                  0.5,
                  "set Polynomial degree = 2\n"
                  "subsection Time integration\n"
                  "  set Time step control = adaptive\n"
                  "end\n"));

  compare("2D bar, adaptive (contact zone)",
          bar_prm(2,
                  "N-CS++",
                  20,
                  1. / 80.,
                  0.4,
                  "subsection Mesh refinement\n"
                  "  set Refinement interval = 4\n"
                  "  set Maximum level = 2\n"
                  "  set Criteria = contact zone\n"
                  "end\n"));
}
