// A rigid obstacle that moves (Scene/Gmsh/Obstacles, 'moving'): the gap of
// its rows is g_p + nu_p . (d(t) - d(0)), taken at t_{n+1} by the
// displacement step and at t_{n+1} + tau by the projection (12f); the work
// of its contact forces is the column work_obstacles (W_obs).
//
// A bar of length 1 m and height 0.1 m (E = 1 Pa, nu = 0, rho = 1 kg/m^2,
// c = 1 m/s) on rollers, its left end on the plane x = 0:
// - the plane moves into it at v = 0.1 m/s: its contact force is rho c v H
//   = 0.01 N/m (1D characteristics; mean over t in [0.2, 0.8] s within 1 %),
//   the momentum it gives rho v H c per second (over [0.2, 0.8] s), the
//   kinetic energy half the obstacle's work, no penetration, and E +
//   W_visc - W_obs constant for N-CS and N-CS++ (within 1e-10 of the
//   energy scale), non-increasing for N-CI (Theorem 3.2; its contact
//   force oscillates about the mean, within 3 %);
// - the plane 0.05 m away, moving at v: contact at t = 0.5 s (within a
//   step); the plane stopped at t = 0.6 s (d = v min(t, 0.6) - 0.05):
//   the bar leaves it;
// - static, the bar's right end clamped, the plane moved 0.01 m at End
//   time: the force E d H / L = 0.001 N/m;
// - a run resumed from its checkpoint repeats the uninterrupted one (its
//   Obstacles written with other white space);
// - static, a disc pressed into a block presses the same whether it slid
//   one radius on its way or was put there (the rows are linearised where
//   the disc is); with a plane at an angle pushing the bar on rollers
//   E + W_visc - W_obs never rises (the multiplier read from the free
//   component: read from both, it rose by 4e-5 of the energy);
// - refused: a motion that uses x, a motion with one component in 2D, a
//   motion that is not finite at some time (named at that time), rand().

#include "tests.h"

namespace
{
  std::string
  bar_prm(const std::string &obstacle,
          const std::string &scheme,
          const std::string &end_time,
          const std::string &extra = "")
  {
    return "set Dimension = 2\nset Output directory = results-moving\n" +
           testing::scene_prm(
             "gmsh",
             "    set Mesh file = bar.msh\n    set Bodies = 1\n"
             "    set Contact tags = 11\n"
             "    set Contact pairs = 1 : obstacle\n"
             "    set Obstacles = " +
               obstacle +
               "\n    set Function constants = v = 0.1\n"
               "    set Dirichlet tags = 12: y\n") +
           "subsection Contact\n  set Search radius = 0.5\nend\n"
           "subsection Material\n  set Young's modulus = 1\n"
           "  set Poisson's ratio = 0\n  set Density = 1\nend\n"
           "subsection Time integration\n  set Scheme = " +
           scheme + "\n  set Time step = 0.0125\n  set End time = " + end_time +
           "\nend\nsubsection Output\n  set Write vtu = false\nend\n" + extra;
  }

  /// The mean of @p column over the rows with t in [a, b].
  double
  mean_over(const testing::Statistics &s,
            const std::string         &column,
            const double               a,
            const double               b)
  {
    const auto t = s.column("time"), v = s.column(column);
    double     sum = 0.;
    unsigned   n   = 0;
    for (unsigned int r = 0; r < t.size(); ++r)
      if (t[r] >= a - 1e-12 && t[r] <= b + 1e-12)
        {
          sum += v[r];
          ++n;
        }
    return sum / n;
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  write_block_msh("bar.msh", {{0., 1., 0., 0.1, 40, 2, 1, 12, 12, 11, 0}});
  const std::string pushing = "plane 0, 0 normal 1, 0 moving v*t, 0";

  // 1. pushed at v
  for (const std::string scheme : {"N-CI", "N-CS", "N-CS++"})
    {
      const Statistics s = run(tight_steps() + bar_prm(pushing, scheme, "0.8"));
      const double     force = mean_over(s, "contact_force", 0.2, 0.8);
      const auto       t = s.column("time"), p = s.column("momentum_x");
      // the momentum gained over [0.2, 0.8] s (row 16 is t = 0.2 s)
      const double gained   = p.back() - p[16];
      const auto   work     = s.column("work_obstacles");
      const auto   energy   = s.column("energy_total");
      const auto   balance  = s.column("energy_balance");
      double       increase = 0., scale = 0., largest = 0.;
      for (unsigned int r = 0; r < energy.size(); ++r)
        {
          scale   = std::max(scale, std::abs(work[r]) + energy[r]);
          largest = std::max(largest, std::abs(balance[r]));
          if (r > 0)
            increase = std::max(increase, balance[r] - balance[r - 1]);
        }
      const double kinetic = s.column("energy_kinetic").back();
      // N-CI's contact force oscillates about the mean
      const double tolerance = scheme == "N-CI" ? 0.03 : 0.01;
      log() << scheme << ": contact force " << fmt(force / 0.01, 3)
            << " rho c v H, momentum gained " << fmt(gained / 0.006, 3)
            << " rho v H c (0.6 s), E_kin " << fmt(kinetic / work.back(), 2)
            << " W_obs, penetration < 1e-12 m, E + W_visc - W_obs "
            << (scheme == "N-CI" ? "non-increasing" : "constant")
            << " (1e-10 of the energy): "
            << check(std::abs(force / 0.01 - 1.) < tolerance &&
                     std::abs(gained / 0.006 - 1.) < tolerance &&
                     std::abs(kinetic / work.back() - 0.5) < 0.01 &&
                     max_of(s.column("max_penetration")) < 1e-12 &&
                     increase < 1e-10 * scale &&
                     (scheme == "N-CI" || largest < 1e-10 * scale))
            << "\n";
    }

  // 2. approaching from 0.05 m, stopped at t = 0.6 s
  {
    const Statistics s =
      run(tight_steps() +
          bar_prm("plane -0.05, 0 normal 1, 0 moving v*min(t, 0.6), 0",
                  "N-CS++",
                  "1.2"));
    const auto [begin, end] = contact_interval(s);
    log() << "approaching at v from 0.05 m, stopped at t = 0.6 s: contact "
             "from t = "
          << fmt(begin, 3) << " s (0.5 s) to t = " << fmt(end, 3)
          << " s, then released: "
          << check(std::abs(begin - 0.5) <= 0.0125 + 1e-9 && end > 0.6 &&
                   end < 1.2 - 1e-9 && s.column("active_nodes").back() == 0)
          << "\n";
  }

  // 3. static: the right end clamped, the plane moved 0.01 m at End time
  {
    std::string text = bar_prm(pushing, "static", "0.1");
    text.replace(text.find("    set Dirichlet tags = 12: y\n"),
                 31,
                 "    set Dirichlet tags = 12: y, 13\n");
    write_block_msh("clamped.msh",
                    {{0., 1., 0., 0.1, 40, 2, 1, 12, 12, 11, 13}});
    text.replace(text.find("bar.msh"), 7, "clamped.msh");
    const Statistics s = run(tight_steps() + text);
    log() << "static, pushed 0.01 m against the clamped end: force "
          << fmt(s.column("contact_force").back() / 0.001, 4) << " E d H/L: "
          << check(std::abs(s.column("contact_force").back() / 0.001 - 1.) <
                   1e-8)
          << "\n";
  }

  // 3b. a disc pressed 0.01 m into a block: static, the path does not
  // matter (the rows are linearised where the disc is at End time), so a
  // disc that slides 0.05 m (one radius) on its way presses as one put
  // there
  {
    write_block_msh("block.msh",
                    {{-0.2, 0.2, 0., 0.1, 40, 10, 1, 12, 13, 0, 0}});
    const auto force = [&](const std::string &motion) {
      return run(tight_steps() +
                 "set Dimension = 2\nset Output directory = results-disc\n" +
                 scene_prm("gmsh",
                           "    set Mesh file = block.msh\n"
                           "    set Bodies = 1\n    set Contact tags = 13\n"
                           "    set Contact pairs = 1 : obstacle\n"
                           "    set Obstacles = sphere 0, 0.15 radius 0.05 "
                           "moving " +
                             motion + "\n    set Dirichlet tags = 12\n") +
                 "subsection Contact\n  set Search radius = 0.5\nend\n"
                 "subsection Material\n  set Young's modulus = 1000\n"
                 "  set Poisson's ratio = 0.3\nend\n"
                 "subsection Time integration\n  set Scheme = static\n"
                 "  set End time = 1\nend\n"
                 "subsection Output\n  set Write vtu = false\nend\n")
        .column("contact_force")
        .back();
    };
    const double slid = force("0.05*t, -0.01*t"), put = force("0.05, -0.01*t");
    log() << "static, a disc slid 0.05 m on its way presses as one put "
             "there: "
          << fmt(slid, 4) << " and " << fmt(put, 4)
          << " N/m: " << check(std::abs(slid - put) < 1e-8 * put && put > 1.)
          << "\n";
  }

  // 3c. a plane at an angle pushes the bar on rollers (y held at the
  // contact nodes): the force along the normal is read from the free
  // component, and E + W_visc - W_obs never rises (its nodes come into
  // contact one after the other: it falls at each)
  {
    const Statistics s = run(
      tight_steps() + bar_prm("plane -0.02, 0.05 normal 1, 0.3 moving v*t, 0",
                              "N-CS++",
                              "0.8"));
    const auto energy  = s.column("energy_total"),
               work    = s.column("work_obstacles"),
               balance = s.column("energy_balance");
    double increase = 0., scale = 0.;
    for (unsigned int r = 0; r < energy.size(); ++r)
      {
        scale = std::max(scale, energy[r] + std::abs(work[r]));
        if (r > 0)
          increase = std::max(increase, balance[r] - balance[r - 1]);
      }
    log() << "a plane at an angle, the contact nodes on rollers: "
             "E + W_visc - W_obs never rises (1e-10 of the energy): "
          << check(increase < 1e-10 * scale && work.back() > 0.) << "\n";
  }

  // 4. resumed from a checkpoint
  {
    const auto checkpointed = [&](const std::string &end, const bool resume) {
      return bar_prm(pushing,
                     "N-CS++",
                     end,
                     "subsection Checkpointing\n  set Interval in steps = 8\n"
                     "  set Resume = " +
                       std::string(resume ? "true" : "false") + "\nend\n");
    };
    std::string full = checkpointed("0.4", false);
    full.replace(full.find("results-moving"), 14, "results-moving-full");
    const Statistics uninterrupted = run(tight_steps() + full);
    run(tight_steps() + checkpointed("0.2", false));
    // (the list written with other white space is the same input)
    std::string again = checkpointed("0.4", true);
    again.replace(again.find(pushing),
                  pushing.size(),
                  "plane 0 ,0 normal   1,0 moving v*t ,  0");
    const Statistics resumed = run(tight_steps() + again);
    const auto [difference, worst] =
      statistics_difference(uninterrupted, resumed);
    log() << "resumed at t = 0.2 s (Obstacles written with other white "
             "space): the statistics agree to 1e-12: "
          << check(difference <= 1e-12) << "\n";
    if (difference > 1e-12)
      log() << "  (" << difference << " in " << worst << ")\n";
  }

  // 5. bad input
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"plane 0, 0 normal 1, 0 moving v*x, 0", "uses x, y or z"},
    {"plane 0, 0 normal 1, 0 moving v*t", "'moving' has 1 components"},
    {"plane 0, 0 normal 1, 0 moving 0.01*t/(0.5 - t), 0",
     "The motion of obstacle 1 (Scene/Gmsh/Obstacles, 'moving') is inf m"},
    {"plane 0, 0 normal 1, 0 moving 0.01*rand(), 0", "uses rand()"}};
  for (const auto &[obstacle, fragment] : cases)
    {
      const std::string message = error_of(bar_prm(obstacle, "N-CS++", "0.8"));
      log() << "refused: " << obstacle << ": "
            << check(message.find(fragment) != std::string::npos) << "\n";
      if (message.find(fragment) == std::string::npos)
        log() << "  (" << message << ")\n";
    }
}
