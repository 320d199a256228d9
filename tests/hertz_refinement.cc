// The Hertz scenes with many contact-zone refinements (once a segmentation
// fault in 3D: a DoF handler was attached to the triangulation while the
// scene refined it): ball on block with 1 global and 3 or 4 contact-zone
// refinements, hertz with 2 global and 5 or 6, set up (mesh, matrices,
// rows, initial step) on 1 and 2 ranks (hertz_refinement.mpirun=2) with the
// same mesh sizes. Then the static ball on block (2 zone refinements)
// against Hertz: the slave nodes on the planes of symmetry get constraint
// rows (without them their neighbours carried their load and the peak
// pressure was 53% too high), and the load sums to P exactly (it was short
// by the polygonal top's missing area): contact radius and peak pressure
// within 5% and 10% of Hertz's.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  auto hertz = [](const std::string &scene,
                  const unsigned int global,
                  const unsigned int zone,
                  const std::string &scheme) {
    const std::string subsection = scene == "hertz" ? "Hertz" : "Ball on block";
    std::ostringstream s;
    s << "set Dimension = " << (scene == "hertz" ? 2 : 3) << "\n"
      << "set Output directory = results-" << global << "-" << zone << "\n"
      << "subsection Scene\n  set Name = " << scene << "\n  subsection "
      << subsection << "\n    set Radius = 1\n    set Block width = 2\n"
      << "    set Block depth = 2\n    set Load = 0.01\n"
      << "    set Initial gap = 0\n    set Contact zone refinements = " << zone
      << "\n  end\nend\n"
      << "subsection Mesh\n  set Initial global refinements = " << global
      << "\nend\n"
      << "subsection Material\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Material of body 2\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Time integration\n  set Scheme = " << scheme
      << "\n  set End time = 0\nend\n"
      << "subsection Output\n  set Write vtu = false\nend\n";
    return s.str();
  };

  for (const auto &[scene, global, zone] :
       {std::make_tuple("ball on block", 1u, 3u),
        std::make_tuple("ball on block", 1u, 4u),
        std::make_tuple("hertz", 2u, 5u),
        std::make_tuple("hertz", 2u, 6u)})
    {
      const Statistics s = run(hertz(scene, global, zone, "N-CS++"));
      log() << scene << ", " << global << " global and " << zone
            << " contact-zone refinements: set up, " << s.column("cells")[0]
            << " cells, " << s.column("dofs")[0] << " DoFs\n";
    }

  // static ball on block: P = 0.01 N, R = 1 m, E = 1 Pa, nu = 0.3 for both
  const double     E_star = 1. / (2. * (1. - 0.3 * 0.3));
  const double     P = 0.01, R = 1.;
  const double     a  = std::cbrt(3. * P * R / (4. * E_star));
  const double     p0 = 3. * P / (2. * M_PI * a * a);
  const Statistics s  = run(hertz("ball on block", 1, 2, "static"));
  // the quarter model's active area pi a_h^2 / 4
  const double a_h  = std::sqrt(4. * s.column("active_measure").back() / M_PI);
  const double p0_h = s.column("max_contact_pressure").back();
  log() << "static ball on block, 2 zone refinements: a_h/a = "
        << fmt(a_h / a, 2) << ", p0_h/p0 = " << fmt(p0_h / p0, 2) << ": "
        << check(std::abs(a_h / a - 1.) < 0.05 &&
                 std::abs(p0_h / p0 - 1.) < 0.1)
        << "\n";
}
