// Several rigid obstacles and curved ones (Scene/Gmsh/Obstacles), against
// the statics a wrong normal, gap or pair would break:
//
// 1. A ring (radii 0.3 and 0.4 m, 48 x 3 cells, rho = 100 kg/m^3) under
//    gravity in a V-groove of two half-spaces (normals (1, 1) and (-1, 1)),
//    static, held against turning by a roller (x fixed) at its inner top:
//    every row of a flank has the flank's normal, so the forces
//    satisfy F1 = F2 and (F1 + F2)/sqrt(2) = the weight rho g |ring|
//    exactly (|ring| the area of the 48-gon ring).
// 2. The same ring resting on two rollers, discs of radius 0.2 m whose
//    centres lie on the lines at 45 degrees through the ring's nodes at 225
//    and 315 degrees: each roller pushes along that line, F1 = F2 and
//    (F1 + F2)/sqrt(2) = the weight (within 1e-3: the rows beside the
//    contact node lean a little).
// 3. The ring dropped into the groove at 1 m/s: it meets both flanks at
//    the step where the free flight closes the gap (the trapezoidal rule
//    integrates the fall under gravity exactly), with equal forces on
//    both, no penetration, and E + W_visc never growing.
// 4. 3D: a cube falling onto a rigid cylinder meets it along the line of
//    its top (all nodes of that line at once), when the free flight closes
//    the gap.
// 5. Bad input is refused naming the entry.

#include <cmath>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>

#include "tests.h"

namespace
{
  /// A ring of nt x nr quadrilaterals about (0, yc), radii r1 < r2: cells
  /// 1, outer boundary 11, the two inner edges beside the top 12.
  void
  write_ring(const std::string &file,
             const double       r1,
             const double       r2,
             const double       yc,
             const unsigned int nt,
             const unsigned int nr)
  {
    std::ostringstream nodes, elements;
    nodes << std::setprecision(17);
    const double pi = 3.14159265358979323846;
    for (unsigned int j = 0; j <= nr; ++j)
      for (unsigned int i = 0; i < nt; ++i)
        {
          const double r = r1 + (r2 - r1) * j / nr, a = 2. * pi * i / nt;
          nodes << j * nt + i + 1 << " " << r * std::cos(a) << " "
                << yc + r * std::sin(a) << " 0\n";
        }
    const auto node = [&](const unsigned int i, const unsigned int j) {
      return j * nt + i % nt + 1;
    };
    unsigned int n = 0;
    for (unsigned int j = 0; j < nr; ++j)
      for (unsigned int i = 0; i < nt; ++i)
        elements << ++n << " 3 2 1 1 " << node(i, j) << " " << node(i + 1, j)
                 << " " << node(i + 1, j + 1) << " " << node(i, j + 1) << "\n";
    for (unsigned int i = 0; i < nt; ++i)
      elements << ++n << " 1 2 11 11 " << node(i, nr) << " " << node(i + 1, nr)
               << "\n";
    // the two inner edges beside the top (90 degrees)
    for (const unsigned int i : {nt / 4 - 1, nt / 4})
      elements << ++n << " 1 2 12 12 " << node(i, 0) << " " << node(i + 1, 0)
               << "\n";
    testing::write_msh(file, nt * (nr + 1), nodes.str(), n, elements.str());
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  const double pi = 3.14159265358979323846;
  // the ring's centre 0.6 m above the groove's vertex: 0.6/sqrt(2) - 0.4 =
  // 0.0243 m from each flank
  const double yc = 0.6;
  write_ring("ring.msh", 0.3, 0.4, yc, 48, 3);
  const double weight =
    100. * 9.81 * 24. * std::sin(2. * pi / 48.) * (0.4 * 0.4 - 0.3 * 0.3);
  const auto prm = [](const std::string &obstacles,
                      const std::string &time_integration) {
    return "set Dimension = 2\nset Output directory = results-obstacles\n" +
           scene_prm("gmsh",
                     "    set Mesh file = ring.msh\n    set Bodies = 1\n"
                     "    set Contact tags = 11\n"
                     "    set Contact pairs = 1 : obstacle 1, 1 : obstacle 2\n"
                     "    set Gravity = 0, -9.81\n" +
                       obstacles) +
           "subsection Material\n  set Young's modulus = 1e7\n"
           "  set Poisson's ratio = 0.3\n  set Density = 100\n"
           "  set Viscous shear modulus = 20\nend\n"
           "subsection Time integration\n" +
           time_integration +
           "end\nsubsection Output\n  set Write vtu = false\nend\n";
  };
  const std::string groove =
    "    set Obstacles = plane 0, 0 normal 1, 1; plane 0, 0 normal -1, 1\n";
  // (frictionless, the ring could turn and, on the rollers, slide: a
  // roller at the inner top holds it, pushing along x only)
  const std::string statics = "  set Scheme = static\n";
  const std::string held    = "    set Dirichlet tags = 12: x\n";
  {
    const Statistics s  = run(prm(groove + held, statics));
    const double     f1 = s.column("contact_force_pair1").back();
    const double     f2 = s.column("contact_force_pair2").back();
    log() << "ring in the V-groove, static: flank forces " << fmt(f1, 6) << ", "
          << fmt(f2, 6) << " N/m, (F1 + F2)/sqrt(2) / weight "
          << fmt((f1 + f2) / std::sqrt(2.) / weight, 8) << ": "
          << check(std::abs(f1 - f2) < 1e-8 * f1 &&
                   std::abs((f1 + f2) / std::sqrt(2.) / weight - 1.) < 1e-8)
          << "\n";
  }
  {
    // roller centres on the lines at 45 degrees through the ring's nodes
    // at 225 and 315 degrees, 0.2 m beyond them (a gap of 0.001 m)
    const double      reach = (0.4 + 0.2 + 0.001) / std::sqrt(2.);
    const std::string rollers =
      "    set Obstacles = sphere " + std::to_string(-reach) + ", " +
      std::to_string(yc - reach) + " radius 0.2; sphere " +
      std::to_string(reach) + ", " + std::to_string(yc - reach) +
      " radius 0.2\n";
    const Statistics s  = run(prm(rollers + held, statics));
    const double     f1 = s.column("contact_force_pair1").back();
    const double     f2 = s.column("contact_force_pair2").back();
    log() << "ring on two rollers, static: roller forces " << fmt(f1, 6) << ", "
          << fmt(f2, 6) << " N/m, (F1 + F2)/sqrt(2) / weight "
          << fmt((f1 + f2) / std::sqrt(2.) / weight, 4) << ": "
          << check(std::abs(f1 - f2) < 1e-8 * f1 &&
                   std::abs((f1 + f2) / std::sqrt(2.) / weight - 1.) < 1e-3)
          << "\n";
  }
  {
    // dropped at 1 m/s: the outer nodes at 225 and 315 degrees (the
    // nearest to the flanks) are 0.6/sqrt(2) - 0.4 from them, closed by a
    // fall of sqrt(2) times that: -v t - g t^2/2 = -d gives t
    const double     d = std::sqrt(2.) * (yc / std::sqrt(2.) - 0.4);
    const double     t = (-1. + std::sqrt(1. + 2. * 9.81 * d)) / 9.81;
    const Statistics s =
      run(prm(groove + "    set Initial velocities = 0, -1\n",
              "  set Time step = 0.001\n  set End time = 0.1\n"));
    const auto first     = contact_interval(s).first;
    const auto f1        = s.column("contact_force_pair1");
    const auto f2        = s.column("contact_force_pair2");
    const auto energy    = s.column("energy_balance");
    double     asymmetry = 0., growth = 0., scale = 0.;
    for (unsigned int r = 1; r < f1.size(); ++r)
      {
        asymmetry = std::max(asymmetry, std::abs(f1[r] - f2[r]));
        scale     = std::max(scale, f1[r]);
        growth    = std::max(growth, energy[r] - energy[r - 1]);
      }
    log() << "ring dropped into the groove: first contact at t = "
          << fmt(first, 4) << " s (free flight closes the gap at " << fmt(t, 4)
          << " s), flank forces equal, no penetration, "
          << "E + W_visc not growing: "
          << check(first >= t && first <= t + 0.0011 &&
                   asymmetry < 1e-8 * scale &&
                   max_of(s.column("max_penetration")) < 1e-12 &&
                   growth < 1e-9 * s.column("energy_total")[0])
          << "\n";
  }

  {
    // 3D: a cube [0, 0.2]^3 (4^3 cells) 0.0102 m above a rigid cylinder of
    // radius 1 about the axis along z through (0.1, -1, 0.1), falling at
    // 1 m/s: its bottom meets the cylinder's top line first (the next
    // lines of nodes, 0.05 m aside, are 0.00125 m farther, more than the
    // step's 0.0005 m of travel), all 5 nodes
    // of the line x = 0.1 at once (measuring the distance without taking
    // out the axial part would put the nodes off z = 0.1 farther away)
    std::ostringstream nodes, elements;
    nodes << std::setprecision(17);
    const unsigned int n = 4;
    const auto index     = [&](unsigned int i, unsigned int j, unsigned int k) {
      return 1 + i + (n + 1) * (j + (n + 1) * k);
    };
    for (unsigned int k = 0; k <= n; ++k)
      for (unsigned int j = 0; j <= n; ++j)
        for (unsigned int i = 0; i <= n; ++i)
          nodes << index(i, j, k) << " " << 0.2 * i / n << " "
                << 0.0102 + 0.2 * j / n << " " << 0.2 * k / n << "\n";
    unsigned int m = 0;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = 0; i < n; ++i)
          elements << ++m << " 5 2 1 1 " << index(i, j, k) << " "
                   << index(i + 1, j, k) << " " << index(i + 1, j + 1, k) << " "
                   << index(i, j + 1, k) << " " << index(i, j, k + 1) << " "
                   << index(i + 1, j, k + 1) << " "
                   << index(i + 1, j + 1, k + 1) << " "
                   << index(i, j + 1, k + 1) << "\n";
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int i = 0; i < n; ++i)
        elements << ++m << " 3 2 10 10 " << index(i, 0, k) << " "
                 << index(i + 1, 0, k) << " " << index(i + 1, 0, k + 1) << " "
                 << index(i, 0, k + 1) << "\n";
    write_msh(
      "cube.msh", (n + 1) * (n + 1) * (n + 1), nodes.str(), m, elements.str());
    const Statistics s =
      run("set Dimension = 3\nset Output directory = results-obstacles-3d\n" +
          scene_prm("gmsh",
                    "    set Mesh file = cube.msh\n    set Bodies = 1\n"
                    "    set Contact tags = 10\n"
                    "    set Contact pairs = 1 : obstacle 1\n"
                    "    set Obstacles = cylinder 0.1, -1, 0.1 axis 0, 0, 1 "
                    "radius 1\n"
                    "    set Initial velocities = 0, -1, 0\n") +
          "subsection Material\n  set Young's modulus = 1e4\n"
          "  set Poisson's ratio = 0.3\nend\n"
          "subsection Time integration\n  set Time step = 0.0005\n"
          "  set End time = 0.012\nend\n"
          "subsection Output\n  set Write vtu = false\nend\n");
    const auto   time   = s.column("time");
    const auto   active = s.column("active_nodes");
    unsigned int first  = 0;
    while (first < active.size() && active[first] == 0)
      ++first;
    log() << "cube falling on a cylinder (3D): first contact at t = "
          << (first < time.size() ? fmt(time[first], 4) : std::string("-"))
          << " s (gap closed at 0.0102 s), with "
          << (first < active.size() ? active[first] : 0)
          << " active nodes (the 5 of the line on its top): "
          << check(first < time.size() && time[first] >= 0.0102 &&
                   time[first] <= 0.0102 + 0.0005 && active[first] == 5)
          << "\n";
  }

  const std::vector<std::pair<std::string, std::string>> cases = {
    {"    set Obstacles = plane 0, 0 normal 1, 1\n",
     "names obstacle 2, but Scene/Gmsh/Obstacles has 1"},
    {"    set Obstacles = plane 0, 0 normal 1, 1; plane 0, 0 normal -1, 1; "
     "sphere 0, -5 radius 1\n",
     "obstacle 3 is in no pair"},
    {"    set Obstacles = plane 0, 0 normal 0, 0; plane 0, 0 normal -1, 1\n",
     "must have a length > 0"},
    {"    set Obstacles = sphere 0, 0 radius -1; plane 0, 0 normal -1, 1\n",
     "the radius must lie in (0, 1e15] m"},
    {"    set Obstacles = cylinder 0, 0, 0 axis 0, 0, 1 radius 1; plane 0, 0 "
     "normal -1, 1\n",
     "a cylinder is a 3D obstacle"},
    {"    set Obstacles = box 0, 0; plane 0, 0 normal -1, 1\n",
     "is no 'plane x, y[, z] normal a, b[, c]'"},
    {groove + "    set Obstacle point = 0, 0\n",
     "Obstacles replaces Obstacle point and Obstacle normal"}};
  for (const auto &[entries, fragment] : cases)
    {
      const std::string message = error_of(prm(entries, statics));
      log() << "refused: " << check(message.find(fragment) != std::string::npos)
            << "\n";
      if (message.find(fragment) == std::string::npos)
        log() << "  (" << message << ")\n";
    }
  log() << "refused ('obstacle' among several): "
        << check(
             error_of(
               std::regex_replace(prm(groove, statics),
                                  std::regex("1 : obstacle 1, 1 : obstacle 2"),
                                  "1 : obstacle"))
               .find("name each as 'obstacle k'") != std::string::npos)
        << "\n";
}
