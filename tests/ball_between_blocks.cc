// Three bodies: a cylinder (2D, scene "hertz") or a ball (3D, "ball on
// block") between two elastic blocks, 'Upper block = true' (R = 1, E = 1,
// nu = 0.3; half or quarter model). Static, the load P on the upper block's
// top: the curved body is refined once more than the blocks, so it is the
// slave of both pairs against the flat blocks, every row's normal is
// vertical, and each pair's normal forces sum to the meshed share of P
// (P/2 in 2D, P/4 in 3D) to 1e-8; each pair's contact half-width (2D,
// its active measure) or radius (3D, from pi a^2/4) is within 10% (2D) or
// 20% (3D, a coarse mesh) of Hertz's b = sqrt(4PR/(pi E*)) or
// a = (3PR/(4E*))^{1/3}, and the two pairs agree with each other to 10%.
// Dropped (2D, N-CS++, E = 100, the cylinder and the upper block at
// 0.2 m/s, gaps 0.01 m): the cylinder reaches the lower block first, the
// upper block then reaches the cylinder; E + W never increases (Theorem
// 3.2); nothing penetrates.
// On two MPI ranks (ball_between_blocks.mpirun=2) with the same output.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double E_star = 1. / (2. * (1. - 0.3 * 0.3)), R = 1.;
  auto         prm = [](const unsigned int dim,
                const std::string &scheme,
                const std::string &entries,
                const std::string &extra) {
    const std::string scene = dim == 2 ? "hertz" : "ball on block";
    return "set Dimension = " + std::to_string(dim) +
           "\nset Output directory = results-" + std::to_string(dim) + "-" +
           scheme + "\n" +
           scene_prm(scene,
                     "    set Upper block = true\n"
                             "    set Extra refinements of the curved body = 1\n" +
                       entries) +
           "subsection Material\n  set Poisson's ratio = 0.3\nend\n"
                   "subsection Material of body 2\n  set Poisson's ratio = 0.3\n"
                   "end\n"
                   "subsection Time integration\n  set Scheme = " +
           scheme +
           "\nend\n"
                   "subsection Output\n  set Write vtu = false\nend\n" +
           extra;
  };

  // static
  for (const unsigned int dim : {2u, 3u})
    {
      const double     P = dim == 2 ? 0.005 : 0.01;
      const Statistics s =
        run(prm(dim,
                "static",
                "    set Initial gap = 0\n    set Load = " + fmt(P) +
                  "\n    set Block width = 2\n    set Block depth = 2\n"
                  "    set Contact zone refinements = " +
                  (dim == 2 ? "4" : "1") + "\n",
                "subsection Mesh\n  set Initial global refinements = " +
                  std::string(dim == 2 ? "2" : "1") + "\nend\n"));
      const double share = P / (dim == 2 ? 2. : 4.);
      const double size  = dim == 2 ? std::sqrt(4. * P * R / (M_PI * E_star)) :
                                      std::cbrt(3. * P * R / (4. * E_star));
      const double tolerance = dim == 2 ? 0.1 : 0.2;
      log() << dim << "D, static:\n";
      std::vector<double> sizes;
      for (const std::string pair : {"pair1", "pair2"})
        {
          const double force   = s.column("contact_force_" + pair).back();
          const double measure = s.column("active_measure_" + pair).back();
          sizes.push_back(dim == 2 ? measure : std::sqrt(4. * measure / M_PI));
          log() << "  " << pair << ": normal forces / share of P "
                << fmt(force / share, 3) << ": "
                << check(std::abs(force / share - 1.) <= 1e-8)
                << ", contact size / Hertz's " << fmt(sizes.back() / size, 2)
                << ": "
                << check(std::abs(sizes.back() / size - 1.) <= tolerance)
                << "\n";
        }
      log() << "  the pairs agree: "
            << check(std::abs(sizes[0] / sizes[1] - 1.) <= 0.1)
            << "; no penetration: "
            << check(s.column("max_penetration").back() <= 1e-12) << "\n";
    }

  // dropped (E = 100 Pa: a wave crosses the cylinder in 0.2 s, so that its
  // top slows down and the upper block catches up within the run)
  {
    const double     tau = 0.005;
    const Statistics s   = run(
      prm(2,
          "N-CS++",
          "    set Initial gap = 0.01\n    set Load = 0\n"
            "    set Drop velocity = 0.2\n    set Block width = 2\n"
            "    set Block depth = 2\n    set Contact zone refinements = 3\n",
          "subsection Mesh\n  set Initial global refinements = 1\nend\n"
            "subsection Material\n  set Young's modulus = 100\nend\n"
            "subsection Material of body 2\n  set Young's modulus = 100\nend\n"
            "subsection Time integration\n  set Time step = " +
            fmt(tau) + "\n  set End time = 0.6\nend\n"));
    const auto time     = s.column("time");
    double     first[2] = {-1., -1.};
    for (unsigned int k = 0; k < 2; ++k)
      {
        const auto active =
          s.column("active_nodes_pair" + std::to_string(k + 1));
        for (unsigned int i = 0; i < time.size() && first[k] < 0.; ++i)
          if (active[i] > 0)
            first[k] = time[i];
      }
    log() << "2D, dropped: the cylinder reaches the lower block at "
          << fmt(first[0], 2) << " s, the upper block reaches the cylinder at "
          << fmt(first[1], 2)
          << " s: " << check(first[0] > 0. && first[1] > first[0]) << "\n";
    log() << "  E + W non-increasing: "
          << check(max_energy_increase(s) <=
                   1e-10 * s.column("energy_total")[0])
          << "; no penetration: "
          << check(max_of(s.column("max_penetration")) <= 1e-12) << "\n";
  }
}
