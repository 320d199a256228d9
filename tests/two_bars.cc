// Two bars meeting head-on at +-v0 (each half is the exact bar impact), with
// N-CS++, matching and non-matching meshes at the interface, 2D and 3D
// (and on two MPI ranks, two_bars.mpirun=2, with the same output): contact
// begins and ends within 2 tau + h/c of g0/v0 and g0/v0 + 2L/c; the maximum
// nodal contact pressure is within 15% of rho c v0 (the mean pressure, force
// over active area, is printed too); each bar rebounds with its speed within
// 5% of v0; the total momentum is conserved to 1e-10 of one bar's (with
// the CG tolerance at 1e-14: momentum is exact up to the solver); the
// relative normal velocity at persistently active nodes is zero to solver
// tolerance; E_total never increases. The bars' mean displacements at T are
// within the contact timing's tolerance times v0 = 1 m/s of the exact
// -+0.3 m, and their sum (the equal bars' common centre of mass) stays zero
// to 1e-10 m.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  struct Case
  {
    unsigned int dim, along, across_1, across_2;
  };
  for (const Case c : {Case{2, 40, 4, 4},
                       Case{2, 40, 8, 11},
                       Case{3, 20, 2, 2},
                       Case{3, 40, 4, 5}})
    {
      const double h = 1. / c.along, tau = h / 2., L = 1., H = 0.1, g0 = 0.1;
      std::ostringstream extra;
      extra << scene_prm("two bars",
                         "    set Cells across = " +
                           std::to_string(c.across_1) +
                           "\n    set Cells across body 2 = " +
                           std::to_string(c.across_2) + "\n")
            // momentum is conserved to the linear solver's tolerance
            << tight_steps()
            // (the error norm is not checked here: at the output times)
            << "subsection Postprocess\n  subsection Error energy norm\n"
            << "    set Interval = output times\n  end\nend\n";
      const Statistics s =
        run(bar_prm(c.dim, "N-CS++", c.along, tau, 2.5, extra.str()));
      log() << c.dim << "D, " << c.across_1 << " and " << c.across_2
            << " cells across:\n";

      const auto [begin, end] = contact_interval(s);
      const double tolerance  = 2. * tau + h;
      log() << "  contact from " << fmt(begin) << " to " << fmt(end) << ": "
            << check(std::abs(begin - g0) <= tolerance &&
                     std::abs(end - (g0 + 2. * L)) <= tolerance)
            << "\n";

      const double p_max  = max_of(s.column("max_contact_pressure"));
      double       p_mean = 0.;
      const auto   force  = s.column("contact_force");
      const auto   area   = s.column("active_measure");
      for (unsigned int i = 0; i < force.size(); ++i)
        if (area[i] > 0.)
          p_mean = std::max(p_mean, force[i] / area[i]);
      log() << "  max nodal pressure / (rho c v0) = " << fmt(p_max, 2)
            << ", max mean pressure = " << fmt(p_mean, 2) << ": "
            << check(std::abs(p_max - 1.) <= 0.15) << "\n";

      const double mass = L * (c.dim == 2 ? H : H * H);
      const double p2   = s.column("momentum_x_body2").back();
      const double p1   = s.column("momentum_x").back() - p2;
      log() << "  rebound velocities / v0 = " << fmt(p1 / mass, 2) << ", "
            << fmt(p2 / mass, 2) << ": "
            << check(std::abs(-p1 / mass - 1.) <= 0.05 &&
                     std::abs(p2 / mass - 1.) <= 0.05)
            << "\n";

      const auto   d1 = s.column("mean_displacement_x_body1");
      const auto   d2 = s.column("mean_displacement_x_body2");
      const double position_error =
        std::max(std::abs(d1.back() + 0.3), std::abs(d2.back() - 0.3));
      double centre = 0.;
      for (unsigned int i = 0; i < d1.size(); ++i)
        centre = std::max(centre, std::abs(d1[i] + d2[i]));
      log() << "  positions at T: " << fmt(d1.back(), 2) << ", "
            << fmt(d2.back(), 2) << " m: " << check(position_error <= tolerance)
            << ", common centre of mass fixed: " << check(centre <= 1e-10)
            << "\n";

      const auto momentum = s.column("momentum_x");
      double     drift    = 0.;
      for (const double p : momentum)
        drift = std::max(drift, std::abs(p - momentum[0]));
      log() << "  total momentum conserved to 1e-10: "
            << check(drift <= 1e-10 * mass) << "\n";

      const double vn_max = persistent_normal_velocity(s).first;
      log() << "  relative normal velocity at active nodes zero: "
            << check(vn_max < 1e-8) << "\n";
      log() << "  E_total non-increasing: "
            << check(max_energy_increase(s) <=
                     1e-10 * s.column("energy_total")[0])
            << "\n";
    }
}
