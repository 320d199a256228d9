// Body force, Neumann traction and Dirichlet data, without contact (the wall
// is far away): a bar clamped at x = L, at rest, is suddenly loaded (a) by an
// axial body force b, (b) by an axial traction t on its free end x = 0. The
// discrete energy E_kin + 1/2 u^T A u - f^T u stays zero (to 1e-8 of the
// static strain energy), and its elastic part swings down to minus the
// static strain energy, b^2 L^3 A/(6E) resp. t^2 L A/(2E), when the bar
// passes its static state: within 1% for the body force (a smooth motion),
// within 3% for the traction (the static state is reached only for an instant,
// by a sharp front that P1/Newmark dispersion smears). Momentum is not
// conserved (the clamp takes force).

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double L = 1., H = 0.1, E = 1.;
  for (const unsigned int dim : {2u, 3u})
    for (const bool traction : {false, true})
      {
        const double      load = 0.2;
        const std::string extra =
          scene_entries("Bar impact",
                        std::string("    set Initial gap = 100\n") +
                          "    set Impact velocity = 0\n"
                          "    set Fixed far end = true\n" +
                          (traction ? "    set End traction = 0.2\n" :
                                      "    set Body force = 0.2\n"));
        const Statistics s =
          run(bar_prm(dim, "N-CS++", dim == 2 ? 40 : 20, 0.0125, 2.5, extra));
        const double area = (dim == 2 ? H : H * H);
        const double static_energy =
          traction ? load * load * L * area / (2. * E) :
                     load * load * L * L * L * area / (6. * E);
        const auto e        = s.column("energy_total");
        const auto el       = s.column("energy_elastic");
        const auto momentum = s.column("momentum_x");
        double     drift = 0., minimum = 0.;
        for (unsigned int i = 0; i < e.size(); ++i)
          {
            drift   = std::max(drift, std::abs(e[i]));
            minimum = std::min(minimum, el[i]);
          }
        log() << dim << "D, " << (traction ? "end traction" : "body force")
              << ":\n  energy stays zero: "
              << check(drift <= 1e-8 * static_energy)
              << "\n  min elastic energy / static strain energy = "
              << fmt(-minimum / static_energy, 3) << ": "
              << check(std::abs(-minimum / static_energy - 1.) <
                       (traction ? 0.03 : 0.01))
              << "\n  momentum changes: "
              << check(max_of(momentum) - min_of(momentum) > 0.1 * load * area)
              << "\n";
      }
}
