// The criterion curved boundary: the cells on a curved boundary kept at
// Maximum level, so that a body's mass is the finest level's. The cells
// are bilinear (trilinear) in their vertices: a coarse cell on the ball's
// circle cuts a segment off it.
// - 2D, the Hertz drop of prm/hertz_drop_adaptive.prm in free flight
//   (dropped at 0.5 m/s from 0.1 m, no load, to 0.15 s; levels 1 to 3,
//   Initial contact refinements 1, every 2 steps): as given (Kelly of the
//   velocity and the contact zone) the ball's momentum is below that of
//   the uniform level-3 mesh by more than 0.1 % in every row (measured
//   0.66-0.96 %); with curved boundary added it equals it to 1e-12 in every
//   row, on fewer than a quarter of its cells.
// - 3D, the ball on the block of prm/ball_drop_adaptive.prm (levels 0 to 2,
//   Initial contact refinements 1, to 0.06 s before contact): the same
//   against the uniform level-2 mesh, with the consistent mass (the
//   momentum of the lumped mass, a nodal quadrature, is not the exact
//   integral of rho u_dot on non-affine trilinear cells: the interior
//   cells' refinement changes it too; in 2D the trapezoidal rule
//   integrates a bilinear cell's Jacobian exactly).
// With one initial contact refinement for two levels, the curved cells
// reach Maximum level before t = 0 by the criterion's own rounds.
// - A scene without a curved boundary (the bar) warns that the criterion
//   flags no cell (what the run prints, read back).
// Also on two MPI ranks (curved_boundary.mpirun=2), with the same output.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const auto example = [](const std::string &name) {
    std::ifstream     in(std::string(DYNCONTACT_PRM_DIR) + "/" + name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  // the length of the ball's momentum in every row (body 1: the total
  // less the block's)
  const auto ball_momentum = [](const Statistics &s) {
    std::vector<double> p(s.column("time").size(), 0.);
    for (const std::string d : {"x", "y", "z"})
      for (unsigned int i = 0; i < p.size(); ++i)
        p[i] += std::pow(s.column("momentum_" + d)[i] -
                           s.column("momentum_" + d + "_body2")[i],
                         2);
    for (double &x : p)
      x = std::sqrt(x);
    return p;
  };

  struct Case
  {
    std::string  name, file, subsection;
    unsigned int coarse, finest;
    double       gap, end;
    std::string  mass;
  };
  for (const Case &c : {Case{"2D Hertz drop",
                             "hertz_drop_adaptive.prm",
                             "Hertz",
                             1,
                             3,
                             0.1,
                             0.15,
                             "lumped"},
                        Case{"3D ball on block",
                             "ball_drop_adaptive.prm",
                             "Ball on block",
                             0,
                             2,
                             0.1,
                             0.06,
                             "consistent"}})
    {
      std::ostringstream common;
      common << example(c.file) << "subsection Output\n  set Write vtu = "
             << "false\nend\nsubsection Scene\n  subsection " << c.subsection
             << "\n    set Load = 0\n    set Drop velocity = 0.5\n"
             << "    set Initial gap = " << c.gap
             << "\n  end\nend\nsubsection Time integration\n  set End time = "
             << c.end << "\n  set Mass matrix = " << c.mass
             << "\nend\nsubsection Mesh\n  set Initial global "
             << "refinements = " << c.coarse << "\nend\n"
             << "subsection Mesh refinement\n  set Minimum level = " << c.coarse
             << "\n  set Maximum level = " << c.finest
             << "\n  set Initial contact refinements = 1\n";
      const Statistics uniform =
        run(common.str() +
            "  set Refinement interval = 0\n  set Initial contact "
            "refinements = 0\nend\nsubsection Mesh\n  set Initial global "
            "refinements = " +
            std::to_string(c.finest) +
            "\nend\nset Output directory = " + "output-uniform\n");
      const Statistics given =
        run(common.str() + "end\nset Output directory = output-given\n");
      const Statistics curved =
        run(common.str() + "  set Criteria = kelly velocity, contact zone, "
                           "curved boundary\nend\nset Output directory = "
                           "output-curved\n");
      const double p   = ball_momentum(uniform)[0];
      double       low = 1., off = 0.;
      for (const double x : ball_momentum(given))
        low = std::min(low, x / p);
      for (const double x : ball_momentum(curved))
        off = std::max(off, std::abs(x / p - 1.));
      log() << c.name << ", before contact (" << given.column("time").size()
            << " rows):\n"
            << "  as given, the ball's momentum below the uniform finest "
               "mesh's by more than 0.1 % in every row: "
            << check(1. - low > 1e-3 &&
                     max_of(ball_momentum(given)) / p < 1. - 1e-3)
            << "\n  with curved boundary equal to it to 1e-12 in every row: "
            << check(off <= 1e-12) << "\n  on fewer than a quarter of its "
            << "cells: "
            << check(max_of(curved.column("cells")) <
                     0.25 * uniform.column("cells")[0])
            << "\n";
    }

  // a scene without a curved boundary: what the run prints (rank 0's)
  std::stringstream printed;
  std::streambuf   *stdout_buffer = std::cout.rdbuf(printed.rdbuf());
  run(bar_prm(2,
              "N-CS++",
              10,
              0.05,
              0.2,
              "subsection Mesh refinement\n  set Refinement interval = 2\n"
              "  set Maximum level = 1\n  set Criteria = kelly velocity, "
              "curved boundary\nend\nset Output directory = output-bar\n"));
  std::cout.rdbuf(stdout_buffer);
  log() << "the bar: a warning that curved boundary flags no cell: "
        << check(printed.str().find("Criteria names curved boundary, but no "
                                    "boundary face of the mesh is on a "
                                    "curved manifold") != std::string::npos)
        << "\n";
}
