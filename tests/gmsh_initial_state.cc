// The initial displacement and velocity of a Gmsh scene as functions of x
// (Scene/Gmsh/Initial displacement, Initial velocity, Function constants),
// on a block [0, 1] x [0, 0.5] of 8 x 4 cells (E = 1 Pa, nu = 0, rho = 1)
// and a second block above it:
//
// - a uniform strain u0 = (eps x, 0): the elastic energy at t = 0 is
//   E eps^2 |block| / 2 (exact for linear elements), the velocity zero;
// - a spin about the block's centre, v0 = omega (-(y - 0.25), x - 0.5):
//   the momentum is zero and the kinetic energy with the lumped mass is
//   rho omega^2 sum_i w_i r_i^2 / 2 (w_i the trapezoidal weights of the
//   nodes: the lumped mass), both exactly;
// - the constant 'body': 'if(body == 2, -1, 0)' moves only body 2;
// - bad input named: an expression that does not parse (naming the
//   component), an unknown variable, three components in 2D, a constant
//   named 'body' or 'x', a velocity function beside the constant Initial
//   velocities, a value that is not finite, and a displacement that pushes
//   body 1 into the rigid floor; one that the Dirichlet tags reset to zero
//   is warned of (a constant velocity of a body with a clamped end is a
//   problem of its own, tests/viscous_decay).

#include <cmath>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  write_block_msh("blocks.msh",
                  {{0, 1, 0, 0.5, 8, 4, 1, 10, 0},
                   {0, 1, 1, 1.5, 8, 4, 2, 0, 0}});
  const auto prm = [](const std::string &dir, const std::string &entries) {
    return "set Dimension = 2\nset Output directory = " + dir + "\n" +
           scene_prm("gmsh",
                     "    set Mesh file = blocks.msh\n"
                     "    set Bodies = 1; 2\n" +
                       entries) +
           "subsection Time integration\n  set Scheme = N-CS++\n"
           "  set Time step = 0.01\n  set End time = 0.02\nend\n"
           "subsection Output\n  set Write vtu = false\nend\n";
  };

  // a uniform strain of body 1
  {
    const double     eps = 0.01;
    const Statistics s =
      run(prm("results-strain",
              "    set Initial displacement = if(body == 1, eps*x, 0); 0\n"
              "    set Function constants = eps = 0.01\n"));
    const double elastic = s.column("energy_elastic").front();
    const double exact   = 0.5 * eps * eps * 0.5;
    log() << "uniform strain 0.01: elastic energy at t = 0 " << fmt(elastic, 6)
          << " J/m (exact " << fmt(exact, 6) << "), kinetic "
          << fmt(s.column("energy_kinetic").front(), 3) << ": "
          << check(std::abs(elastic - exact) <= 1e-12 &&
                   s.column("energy_kinetic").front() == 0.)
          << "\n";
  }

  // a spin of body 1 about its centre; body 2 at rest
  {
    const double     omega = 2.;
    const Statistics s =
      run(prm("results-spin",
              "    set Initial velocity = if(body == 1, -omega*(y - 0.25), 0); "
              "if(body == 1, omega*(x - 0.5), 0)\n"
              "    set Function constants = omega = 2\n"));
    double sum = 0.; // sum_i w_i r_i^2 over the 9 x 5 nodes
    for (unsigned int i = 0; i <= 8; ++i)
      for (unsigned int j = 0; j <= 4; ++j)
        {
          const double w = (1. / 8) * (0.5 / 4) *
                           (i == 0 || i == 8 ? 0.5 : 1.) *
                           (j == 0 || j == 4 ? 0.5 : 1.);
          const double x = i / 8. - 0.5, y = j * 0.5 / 4 - 0.25;
          sum += w * (x * x + y * y);
        }
    const double kinetic = s.column("energy_kinetic").front();
    const double exact   = 0.5 * omega * omega * sum;
    log() << "spin at 2 rad/s: kinetic energy at t = 0 " << fmt(kinetic, 6)
          << " J/m (exact " << fmt(exact, 6) << "), momentum ("
          << fmt(s.column("momentum_x").front() + 0., 2) << ", "
          << fmt(s.column("momentum_y").front() + 0., 2) << "): "
          << check(std::abs(kinetic - exact) <= 1e-12 &&
                   std::abs(s.column("momentum_x").front()) <= 1e-14 &&
                   std::abs(s.column("momentum_y").front()) <= 1e-14)
          << "\n";
  }

  // only body 2 moves
  {
    const Statistics s = run(prm("results-body",
                                 "    set Initial velocity = 0; if(body == 2, "
                                 "-1, 0)\n"));
    log() << "'if(body == 2, -1, 0)': momentum of body 2 "
          << fmt(s.column("momentum_y_body2").front(), 6) << ", of all "
          << fmt(s.column("momentum_y").front(), 6) << " (exact -0.5, -0.5): "
          << check(std::abs(s.column("momentum_y_body2").front() + 0.5) <=
                     1e-12 &&
                   std::abs(s.column("momentum_y").front() + 0.5) <= 1e-12)
          << "\n";
  }

  // bad input
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"    set Initial velocity = 0; 2*(x\n", "Initial velocity = '0; 2*(x'"},
    {"    set Initial velocity = 0; w*x\n", "Initial velocity = '0; w*x'"},
    {"    set Initial displacement = 0; 0; 0\n", "has 3 components"},
    {"    set Initial velocity = 0; body\n"
     "    set Function constants = body = 2\n",
     "Function constants: 'body = 2'"},
    {"    set Initial velocity = 0; -1\n"
     "    set Initial velocities = 0, 0; 0, -1\n",
     "replaces Scene/Gmsh/Initial velocities"},
    {"    set Initial velocity = 0; x\n"
     "    set Function constants = x = 1\n",
     "names a constant 'x', which is a variable"},
    {"    set Initial velocity = 1/(x - x); 0\n",
     "Initial velocity is not finite at the node"},
    {"    set Initial displacement = 0; if(body == 1, -0.01, 0)\n"
     "    set Contact tags = 10;\n    set Contact pairs = 1 : obstacle\n"
     "    set Obstacle point = 0, 0\n    set Obstacle normal = 0, 1\n",
     "The initial displacement makes the bodies penetrate"}};
  // a displacement that the clamp of the bottom (tag 10) resets: a warning
  std::ofstream("clamped.prm") << prm("results-clamped",
                                      "    set Initial displacement = 0.01; 0\n"
                                      "    set Dirichlet tags = 10\n");
  const Outcome clamped = run_program("clamped.prm");
  log() << "a displacement of 0.01 m at the clamped bottom: the run warns "
           "that those nodes start at zero: "
        << check(clamped.status == 0 &&
                 clamped.text.find(
                   "warning: the initial displacement is up to 0.01 m at "
                   "nodes that Dirichlet boundaries hold at zero") !=
                   std::string::npos)
        << "\n";

  for (const auto &[entries, fragment] : cases)
    {
      const std::string message = error_of(prm("results-bad", entries));
      log() << "refused: " << entries.substr(4, entries.find('\n') - 4) << ": "
            << check(message.find(fragment) != std::string::npos) << "\n  "
            << message.substr(0, 400) << "\n";
    }
}
