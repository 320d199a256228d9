// Conservation without contact (the wall is far away): a pre-strained bar
// vibrates freely (its slow drift keeps the kinetic energy small compared
// to the vibration). Without viscosity E_kin + E_el stays constant to 1e-8
// relative over 100 steps, for every scheme and both mass matrices; with
// viscosity E_total + viscous dissipation stays constant while E_total
// itself decays; the linear momentum stays constant (no Dirichlet data, no
// loads: Theorem 3.1), and the mean displacement (centre of mass) moves with
// the bar's speed: d(t) = d(0) - v0 t.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double      v0 = 0.001;
  const std::string free_flight =
    scene_entries("Bar impact",
                  "    set Initial gap = 100\n"
                  "    set Impact velocity = 0.001\n"
                  "    set Initial strain = -0.01\n");
  const std::string viscous = "subsection Material\n"
                              "  set Viscous shear modulus = 0.05\n"
                              "  set Viscous Lame parameter = 0.02\n"
                              "end\n";
  const std::string consistent =
    "subsection Time integration\n  set Mass matrix = consistent\nend\n";

  for (const std::string scheme : {"N-CI", "N-CS", "N-CS++"})
    for (const bool with_viscosity : {false, true})
      for (const bool lumped : {true, false})
        {
          const Statistics s =
            run(tight_steps() +
                bar_prm(2,
                        scheme,
                        20,
                        0.025,
                        2.5,
                        free_flight + (with_viscosity ? viscous : "") +
                          (lumped ? "" : consistent)));
          const auto e     = s.column("energy_total");
          const auto w     = s.column("dissipation_viscous");
          const auto px    = s.column("momentum_x");
          const auto py    = s.column("momentum_y");
          const auto t     = s.column("time");
          const auto d     = s.column("mean_displacement_x");
          const auto dy    = s.column("mean_displacement_y");
          double     drift = 0., momentum_drift = 0., centre_drift = 0.;
          for (unsigned int i = 0; i < e.size(); ++i)
            {
              drift = std::max(drift, std::abs(e[i] + w[i] - e[0]));
              momentum_drift =
                std::max(momentum_drift,
                         std::abs(px[i] - px[0]) + std::abs(py[i] - py[0]));
              centre_drift = std::max(centre_drift,
                                      std::abs(d[i] - d[0] + v0 * t[i]) +
                                        std::abs(dy[i] - dy[0]));
            }
          log() << scheme << (with_viscosity ? ", viscous" : ", elastic")
                << (lumped ? ", lumped" : ", consistent") << ", "
                << e.size() - 1 << " steps:\n";
          log() << "  energy (+ dissipation) constant to 1e-8: "
                << check(drift <= 1e-8 * std::abs(e[0])) << "\n";
          if (with_viscosity)
            log() << "  viscous dissipation > half the initial elastic "
                     "energy: "
                  << check(w.back() > 0.5 * s.column("energy_elastic")[0])
                  << "\n";
          log() << "  momentum constant to 1e-10: "
                << check(momentum_drift <= 1e-10 * std::abs(px[0])) << "\n";
          log() << "  mean displacement d(0) - v0 t to 1e-10 v0 T: "
                << check(centre_drift <= 1e-10 * v0 * t.back()) << "\n";
        }
}
