// Hertz impact in 3D (N-CS++): prm/ball_drop_adaptive.prm (the quarter of
// a half ball, R = 1 m, E = 100 Pa, dropping at 0.1 m/s onto a 4 x 2 x 4 m
// block, adaptive mesh) at finest level 3 and tau = 0.02 s, against Hertz's
// quasi-static impact with the mesh's mass m (from the kinetic energy):
// alpha_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5), contact time
// 2.94 alpha_max / v within 5%, peak force 4/3 E* sqrt(R) alpha_max^(3/2)
// within 10% (the clamped block of depth 2 m is stiffer than Hertz's half
// space: finer meshes and steps stay 5-6% above), the ball leaves at v
// within 3%, and the energy minus the transfers never increases. A wrong
// E* (E instead of E/(2(1 - nu^2))) moves the force by 27%.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  std::ifstream in(std::string(DYNCONTACT_PRM_DIR) + "/ball_drop_adaptive.prm");
  std::stringstream text;
  text << in.rdbuf() << "\nset Output directory = results-impact\n"
       << "subsection Mesh refinement\n  set Maximum level = 3\n"
       << "  set Initial contact refinements = 2\nend\n"
       << "subsection Time integration\n  set Time step = 0.02\nend\n"
       << "subsection Output\n  set Write vtu = false\nend\n";
  const Statistics s = run(text.str());

  const double v = 0.1, R = 1., E_star = 100. / (2. * (1. - 0.3 * 0.3));
  const double tau = 0.02;
  // the half ball's mass: four times the quarter's
  const double m = 4. * 2. * s.column("energy_kinetic")[0] / (v * v);
  const double alpha =
    std::pow(15. * m * v * v / (16. * E_star * std::sqrt(R)), 0.4);
  const double t_c   = 2.94 * alpha / v;
  const double F_max = 4. / 3. * E_star * std::sqrt(R) * std::pow(alpha, 1.5);

  const auto [begin, end] = contact_interval(s);
  const double duration   = end - begin + tau;
  const double force      = 4. * max_of(s.column("contact_force"));
  const auto   p = s.column("momentum_y"), p2 = s.column("momentum_y_body2");
  const double rebound = (p.back() - p2.back()) / (m / 4.);

  log() << "contact begins within one step after gap/v = 0.1 s: "
        << check(begin > 0.1 && begin <= 0.1 + tau + 1e-12) << "\n";
  log() << "contact time / Hertz = " << fmt(duration / t_c, 2)
        << ", within 5%: " << check(std::abs(duration / t_c - 1.) <= 0.05)
        << "\n";
  log() << "peak force / Hertz = " << fmt(force / F_max, 3)
        << ", within 10%: " << check(std::abs(force / F_max - 1.) <= 0.1)
        << "\n";
  log() << "rebound velocity within 3% of the impact velocity: "
        << check(std::abs(rebound / v - 1.) <= 0.03) << "\n";
  log() << "E_total - transfers non-increasing: "
        << check(max_energy_increase_of_steps(s) <=
                 1e-10 * s.column("energy_total")[0])
        << "\n";
}
