// Each body its material: the entries of subsection Material take one value
// (for every body) or a list of one value per body.
//
// - Lists that say what 'Material' and 'Material of body 2' said give the
//   same run, bit for bit (the two blocks on a floor from Gmsh).
// - A striker of one material hitting a bar of another (the two bars scene
//   with lists, nu = 0: exact in 1D by characteristics). The striker
//   (E = 4, rho = 1: c1 = 2, impedance Z1 = 2) meets the bar (E = 6,
//   rho = 6: c2 = 1, Z2 = 6) at relative speed V; the contact stress is
//   Z1 Z2 V / (Z1 + Z2), and since Z1 < Z2 and the striker's wave is back at
//   the interface first (2 L / c1 < 2 L / c2), the bars part at 2 L / c1
//   after the impact, the striker's velocity relative to the bar's start
//   turned to V (Z1 - Z2) / (Z1 + Z2). One material for both (a wrong
//   reading) would stop the striker instead. The exact solution of the
//   scene (one material) does not apply then: no error column.
// - Three bodies of three densities falling freely under gravity: each
//   body's momentum is rho_k |body k| g t.
// - A list of another length than one or the number of bodies, and a value
//   out of range in a list, are refused naming the entry (and the body).

#include <cmath>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  // 1. lists equal to the two subsections
  {
    std::ifstream     in(std::string(DYNCONTACT_PRM_DIR) +
                     "/gmsh_blocks_on_floor.prm");
    std::stringstream example;
    example << in.rdbuf();
    std::string prm = example.str();
    prm.replace(prm.find("= meshes/"),
                9,
                "= " + std::string(DYNCONTACT_PRM_DIR) + "/meshes/");
    const std::string common =
      "set Output directory = results-lists\n"
      "subsection Time integration\n  set End time = 0.1\nend\n"
      "subsection Output\n  set Write vtu = false\nend\n";
    const Statistics  two_subsections = run(prm + common);
    const std::string lists =
      "subsection Material\n"
      "  set Young's modulus       = 1000, 100\n"
      "  set Poisson's ratio       = 0.3\n"
      "  set Density               = 1\n"
      "  set Viscous shear modulus = 1, 0.1\n"
      "end\n"
      "subsection Material of body 2\n"
      "  set Young's modulus = 1\n" // unread now (a warning)
      "end\n";
    const Statistics with_lists = run(prm + lists + common);
    const auto difference = statistics_difference(two_subsections, with_lists);
    log() << "two blocks on a floor, lists '1000, 100' etc. against "
             "Material and Material of body 2: "
          << with_lists.rows.size() - 1 << " steps, largest difference "
          << difference.first << ": " << check(difference.first == 0.) << "\n";
  }

  // 2. striker and bar of two materials
  {
    const double      L = 1, H = 0.1, v0 = 0.5, g0 = 0.05;
    const double      rho1 = 1, E1 = 4, rho2 = 6, E2 = 6;
    const double      c1 = std::sqrt(E1 / rho1), Z1 = rho1 * c1;
    const double      c2 = std::sqrt(E2 / rho2), Z2 = rho2 * c2;
    const double      V = 2 * v0, t0 = g0 / v0, tau = 0.00625, h = L / 40;
    const std::string prm =
      "set Dimension = 2\nset Output directory = results-striker\n" +
      scene_prm("two bars",
                "    set Length = 1\n    set Height = 0.1\n"
                "    set Impact velocity = 0.5\n    set Initial gap = 0.05\n"
                "    set Cells along length = 40\n") +
      "subsection Material\n"
      "  set Young's modulus = 4, 6\n"
      "  set Density         = 1, 6\n"
      "  set Poisson's ratio = 0\n"
      "end\n"
      "subsection Time integration\n"
      "  set Scheme = N-CS++\n  set Time step = 0.00625\n"
      "  set End time = 1.5\nend\n"
      "subsection Output\n  set Write vtu = false\nend\n";
    const Statistics s       = run(prm);
    const auto [begin, end]  = contact_interval(s);
    const double duration    = 2 * L / c1;
    const double m1          = rho1 * L * H;
    const double m2          = rho2 * L * H;
    const double p1_exact    = m1 * (-v0 + V * (Z1 - Z2) / (Z1 + Z2));
    const double p2_exact    = m1 * v0 - m2 * v0 - p1_exact;
    const double p2          = s.column("momentum_x_body2").back();
    const double p1          = s.column("momentum_x").back() - p2;
    const double force_exact = Z1 * Z2 * V / (Z1 + Z2) * H;
    const auto   time        = s.column("time");
    const auto   force       = s.column("contact_force");
    double       impulse     = 0.;
    for (unsigned int i = 1; i < time.size(); ++i)
      impulse += 0.5 * (force[i] + force[i - 1]) * (time[i] - time[i - 1]);
    const double impulse_exact = m1 * V * 2 * Z2 / (Z1 + Z2);
    log() << "striker (Z = " << Z1 << ") on a bar (Z = " << Z2 << "): contact ["
          << fmt(begin, 4) << ", " << fmt(end, 4) << "] s, exact [" << fmt(t0)
          << ", " << fmt(t0 + duration)
          << "] s, the start within 2 steps, the release within one cell's "
             "travel in the bar and a step (it lags so on one material "
             "too): "
          << check(std::abs(begin - t0) <= 2 * tau &&
                   std::abs(end - (t0 + duration)) <= h / c2 + tau)
          << "\n  impulse of the contact force " << fmt(impulse)
          << " N s/m, exact " << fmt(impulse_exact) << " (the contact stress "
          << fmt(force_exact / H) << " Pa for " << fmt(duration) << " s): "
          << check(std::abs(impulse - impulse_exact) <= 0.03 * impulse_exact)
          << "\n  momentum after: striker " << fmt(p1) << " (exact "
          << fmt(p1_exact) << "), bar " << fmt(p2) << " (exact "
          << fmt(p2_exact) << ") kg m/s per m: "
          << check(std::abs(p1 - p1_exact) <= 0.03 * std::abs(p1_exact) &&
                   std::abs(p2 - p2_exact) <= 0.03 * std::abs(p2_exact))
          << "\n  no error column (the scene's exact solution is for one "
             "material): "
          << check(!s.has_column("error_energy_norm")) << "\n";
  }

  // 3. three densities in free fall
  {
    write_block_msh("three.msh",
                    {{0, 1, 0, 0.5, 4, 2, 1, 0, 0},
                     {0, 1, 1, 1.5, 4, 2, 2, 0, 0},
                     {0, 2, 2, 2.25, 8, 1, 3, 0, 0}});
    const std::string bodies =
      "set Dimension = 2\nset Output directory = results-three\n" +
      scene_prm("gmsh",
                "    set Mesh file = three.msh\n    set Bodies = 1; 2; 3\n"
                "    set Gravity = 0, -10\n") +
      "subsection Time integration\n"
      "  set Scheme = N-CS++\n  set Time step = 0.01\n"
      "  set End time = 0.1\nend\n"
      "subsection Output\n  set Write vtu = false\nend\n";
    const Statistics s      = run(bodies + "subsection Material\n"
                                           "  set Young's modulus = 100, 200, 300\n"
                                           "  set Density         = 1, 2, 3\n"
                                           "end\n");
    const double     t      = s.column("time").back();
    const double     area[] = {0.5, 0.5, 0.5};
    bool             right  = true;
    log() << "three bodies of densities 1, 2, 3 falling at g = 10 m/s^2, "
             "momentum at t = "
          << fmt(t) << " s:";
    for (unsigned int b = 2; b <= 3; ++b)
      {
        const double p = s.column("momentum_y_body" + std::to_string(b)).back();
        const double exact = -double(b) * area[b - 1] * 10. * t;
        right = right && std::abs(p - exact) <= 1e-9 * std::abs(exact);
        log() << " body " << b << " " << fmt(p) << " (exact " << fmt(exact)
              << ")";
      }
    const double total = s.column("momentum_y").back();
    const double exact = -(1. + 2. + 3.) * 0.5 * 10. * t;
    log() << ", all " << fmt(total) << " (exact " << fmt(exact) << "): "
          << check(right && std::abs(total - exact) <= 1e-9 * std::abs(exact))
          << "\n";

    const std::string length = error_of(bodies + "subsection Material\n"
                                                 "  set Density = 1, 2\n"
                                                 "end\n");
    log() << "a list of 2 values for 3 bodies is refused, naming the entry "
             "and the lengths allowed: "
          << check(length.find("Material/Density has 2 values") !=
                     std::string::npos &&
                   length.find("one per body (3 bodies") != std::string::npos)
          << "\n";
    const std::string range =
      error_of(bodies + "subsection Material\n"
                        "  set Poisson's ratio = 0.3, 0.5, 0\n"
                        "end\n");
    log() << "Poisson's ratio 0.5 for body 2 is refused, naming the entry and "
             "the body: "
          << check(range.find("Material/Poisson's ratio of body 2 must lie "
                              "in the open interval (-1, 0.5)") !=
                   std::string::npos)
          << "\n";
    // (deal.II's list splitting drops a last empty item)
    const std::string trailing = error_of(bodies + "subsection Material\n"
                                                   "  set Density = 1, 2, 3,\n"
                                                   "end\n");
    log() << "a list with a trailing comma is refused, naming the entry: "
          << check(trailing.find("Material/Density = '1, 2, 3,' is refused") !=
                   std::string::npos)
          << "\n";
  }
}
