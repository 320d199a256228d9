// Static Hertz contact in 3D, quarter model of a ball (R = 1, E = 1,
// nu = 0.3) pressed into a block by P = 0.01: the ball's contact zone is
// refined once more than the block's, so that it is the finer side and the
// slave (chosen automatically) against the flat block. Against Hertz's
// a = (3PR/(4E*))^{1/3} and p0 = 3P/(2 pi a^2): the contact radius from the
// active area (pi a_h^2 / 4), the peak nodal pressure and the relative L2
// error of the nodal pressures against p0 sqrt(1 - r^2/a^2) (column
// pressure_error), on two meshes, the error falling with the mesh. With the
// flat block as master every row's normal is vertical, so the normal forces
// sum to P/4 exactly: a wrong boundary weight changes the pressures, and a
// missing row (on the planes of symmetry, say) the profile. Run also on two
// MPI ranks with the same output.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double E_star = 1. / (2. * (1. - 0.3 * 0.3));
  const double P = 0.01, R = 1.;
  const double a  = std::cbrt(3. * P * R / (4. * E_star));
  const double p0 = 3. * P / (2. * M_PI * a * a);

  std::vector<double> errors;
  for (const unsigned int zone : {1u, 2u})
    {
      std::ostringstream prm;
      prm << "set Dimension = 3\n"
          << "set Output directory = results-" << zone << "\n"
          << "subsection Scene\n  set Name = ball on block\n"
          << "  subsection Ball on block\n    set Radius = 1\n"
          << "    set Block width = 2\n    set Block depth = 2\n"
          << "    set Load = 0.01\n    set Initial gap = 0\n"
          << "    set Contact zone refinements = " << zone << "\n"
          << "    set Extra refinements of the curved body = 1\n"
          << "  end\nend\n"
          << "subsection Mesh\n  set Initial global refinements = 1\nend\n"
          << "subsection Material\n  set Poisson's ratio = 0.3\nend\n"
          << "subsection Material of body 2\n  set Poisson's ratio = 0.3\n"
          << "end\n"
          << "subsection Time integration\n  set Scheme = static\nend\n"
          << "subsection Output\n  set Write vtu = false\nend\n";
      const Statistics s = run(prm.str());
      const double     a_h =
        std::sqrt(4. * s.column("active_measure").back() / M_PI);
      const double p0_h  = s.column("max_contact_pressure").back();
      const double error = s.column("pressure_error").back();
      const double force = s.column("contact_force").back();
      errors.push_back(error);
      log() << zone << " zone refinements (+1 of the ball), "
            << s.column("dofs")[0] << " DoFs: a_h/a = " << fmt(a_h / a, 3)
            << ", p0_h/p0 = " << fmt(p0_h / p0, 3)
            << ", pressure error = " << fmt(error, 2) << ": "
            << check(std::abs(a_h / a - 1.) < (zone == 1 ? 0.08 : 0.05) &&
                     std::abs(p0_h / p0 - 1.) < (zone == 1 ? 0.15 : 0.03) &&
                     error < (zone == 1 ? 0.15 : 0.08))
            << "\n";
      log() << "  normal forces / (P/4) = " << fmt(force / (P / 4.), 4) << ": "
            << check(std::abs(force / (P / 4.) - 1.) < 1e-4)
            << "; no penetration: "
            << check(s.column("max_penetration").back() <= 1e-12) << "\n";
    }
  log() << "pressure error falls with the mesh: "
        << check(errors[1] < 0.7 * errors[0]) << "\n";
}
