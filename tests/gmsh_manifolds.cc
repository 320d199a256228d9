// Curved Gmsh boundaries refine onto their manifold (Scene/Gmsh/Manifolds).
// A disc of radius 1 meshed by five quadrilaterals, its boundary (tag 20)
// four chords of a quarter circle each: the mesh's area is measured by the
// run itself, as the momentum rho |Omega_h| v of a body moving at v (the
// lumped mass sums to rho |Omega_h|).
//
// - Global refinements k = 0..3: bound to the circle, the boundary is the
//   regular polygon of 4 2^k sides, area (n/2) sin(2 pi/n) (2, 2.828427,
//   3.061467, 3.121445); not bound, the square of area 2 at every k.
// - An adaptive mesh (the contact zone of the rigid floor below the disc,
//   finest level 2): the first adaptation refines the four boundary cells
//   (every boundary node is within two cell sizes of the floor), the
//   octagon; the second the six cells of level 1 at the five boundary
//   nodes less than two cell sizes (1.53 m) above the floor (at 0, 180,
//   225, 270 and 315 deg), whose six chords of 45 deg each gain (2 sin 22.5
//   deg - sin 45 deg)/2 = 0.029130: area 2 sqrt(2) + 6 x 0.029130 =
//   3.003207; not bound, the area stays 2. On one and on two ranks (the
//   same output).
// - Resumed from a checkpoint written after the adaptation, the run ends
//   as the uninterrupted one.
// - Bad input: a tag that is not on the boundary, a centre that the tag's
//   faces are not around, a cylinder in 2D, an item that is no binding.

#include <filesystem>

#include "tests.h"

namespace
{
  /// The disc of radius 1 around (0, 1.05): an inner square of half-side
  /// 0.3 and four cells to the circle; boundary lines tag 20.
  void
  write_disc(const std::string &file)
  {
    const double c = std::sqrt(0.5), s = 0.3, y0 = 1.05;
    // inner corners 1-4, outer 5-8 (counter-clockwise from lower left)
    const double       x[] = {-s, s, s, -s, -c, c, c, -c};
    const double       y[] = {-s, -s, s, s, -c, -c, c, c};
    std::ostringstream out;
    out << std::setprecision(17)
        << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n";
    for (unsigned int i = 0; i < 8; ++i)
      out << i + 1 << " " << x[i] << " " << y0 + y[i] << " 0\n";
    out << "$EndNodes\n$Elements\n9\n"
        << "1 3 2 1 1 1 2 3 4\n" // centre
        << "2 3 2 1 1 5 6 2 1\n" // below
        << "3 3 2 1 1 2 6 7 3\n" // right
        << "4 3 2 1 1 4 3 7 8\n" // above
        << "5 3 2 1 1 5 1 4 8\n" // left
        << "6 1 2 20 20 5 6\n7 1 2 20 20 6 7\n"
        << "8 1 2 20 20 7 8\n9 1 2 20 20 8 5\n$EndElements\n";
    if (testing::this_rank() == 0)
      std::ofstream(file) << out.str();
    MPI_Barrier(MPI_COMM_WORLD);
  }

  std::string
  disc_prm(const std::string &dir, const std::string &entries)
  {
    return "set Dimension = 2\nset Output directory = " + dir + "\n" +
           testing::scene_prm("gmsh",
                              "    set Mesh file = disc.msh\n"
                              "    set Initial velocity of body 1 = 0, -1\n" +
                                entries) +
           "subsection Time integration\n  set Scheme = N-CS++\n"
           "  set Time step = 0.01\n  set End time = 0.04\nend\n"
           "subsection Output\n  set Write vtu = false\nend\n";
  }

  /// The area rho |Omega_h| v / (rho v) at the last step.
  double
  area_of(const testing::Statistics &s)
  {
    return -s.column("momentum_y").back();
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  write_disc("disc.msh");
  const std::string bound = "    set Manifolds = 20: sphere 0, 1.05\n";

  // 1. global refinements
  for (unsigned int k = 0; k <= 3; ++k)
    {
      const std::string refine = "subsection Mesh\n  set Initial global "
                                 "refinements = " +
                                 std::to_string(k) + "\nend\n";
      const double n     = 4 * std::pow(2., k);
      const double exact = n / 2 * std::sin(2 * M_PI / n);
      const double with =
        area_of(run(disc_prm("results-disc", bound) + refine));
      const double without =
        area_of(run(disc_prm("results-disc", "") + refine));
      log() << k << " global refinements: area bound to the circle "
            << fmt(with, 7) << " (polygon of " << n << " sides "
            << fmt(exact, 7) << "), not bound " << fmt(without, 7) << ": "
            << check(std::abs(with - exact) < 1e-10 &&
                     std::abs(without - 2.) < 1e-10)
            << "\n";
    }

  // 2. an adaptive mesh: the contact zone of the floor y = 0 (the
  // disc's lowest chord 0.34 m above it, within the zone's 0.5 m)
  const std::string adaptive =
    "    set Contact pairs = 1 : obstacle\n"
    "    set Contact tags = 20\n    set Bodies = 1\n"
    "    set Initial velocities = 0, -1\n"
    "    set Obstacle point = 0, 0\n    set Obstacle normal = 0, 1\n";
  const std::string adapt_settings =
    "subsection Mesh refinement\n  set Refinement interval = 1\n"
    "  set Maximum level = 2\n  set Criteria = contact zone\n"
    "  set Refine fraction = 0\n  set Coarsen fraction = 0\n"
    "  subsection Contact zone\n    set Distance = 0.5\n  end\nend\n";
  const auto adaptive_prm = [&](const std::string &dir,
                                const std::string &binding) {
    std::string prm = disc_prm(dir, binding + adaptive);
    prm.replace(prm.find("    set Initial velocity of body 1 = 0, -1\n"),
                43,
                "");
    return prm + adapt_settings;
  };
  const Statistics adapted   = run(adaptive_prm("results-adaptive", bound));
  const Statistics unadapted = run(adaptive_prm("results-flat", ""));
  const double     exact =
    2. * std::sqrt(2.) +
    6. * 0.5 * (2. * std::sin(M_PI / 8.) - std::sin(M_PI / 4.));
  log() << "adaptive: cells " << adapted.column("cells").front() << " -> "
        << adapted.column("cells").back() << ", area bound to the circle "
        << fmt(area_of(adapted), 7) << " (exact " << fmt(exact, 7)
        << "), not bound " << fmt(area_of(unadapted), 7) << ": "
        << check(std::abs(area_of(adapted) - exact) < 1e-10 &&
                 std::abs(area_of(unadapted) - 2.) < 1e-10)
        << "\n";

  // 3. a checkpoint after the adaptation, resumed
  const std::string checkpointed =
    adaptive_prm("results-resumed", bound) +
    "subsection Checkpointing\n  set Interval in steps = 2\nend\n";
  std::string first_half = checkpointed;
  first_half.replace(first_half.find("End time = 0.04"), 15, "End time = 0.02");
  run(first_half);
  const Statistics resumed =
    run(checkpointed + "subsection Checkpointing\n  set Resume = true\nend\n");
  const auto difference = statistics_difference(adapted, resumed);
  log() << "resumed after the adaptation: ends as the uninterrupted run "
           "(largest difference < 1e-10): "
        << check(difference.first < 1e-10) << "\n";

  // 4. bad input
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"    set Manifolds = 21: sphere 0, 1.05\n",
     "binds tag 21, but the mesh file"},
    {"    set Manifolds = 20: sphere 0, 0\n", "the tag is not on this sphere"},
    {"    set Manifolds = 20: cylinder 0, 0, 0 axis 0, 0, 1\n",
     "In 2D a cylinder's section is a circle"},
    {"    set Manifolds = 20 sphere 0, 1.05\n", "is no 'tag: sphere x, y'"}};
  for (const auto &[entry, fragment] : cases)
    log() << "refused, naming the binding: "
          << entry.substr(4, entry.size() - 5) << ": "
          << check(error_of(disc_prm("results-bad", entry)).find(fragment) !=
                   std::string::npos)
          << "\n";
}
