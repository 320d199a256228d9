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
// - The same circle as a CAD curve (OpenCASCADE; tests/cad): a STEP file
//   declared in m, an IGES file declared in mm (the file's unit is
//   honoured) and a STEP file declared in mm whose numbers are metres
//   with 'scale 1000' give the polygons' areas (to the CAD tolerance,
//   1e-6), the adaptive mesh its exact area, and a resumed run the
//   uninterrupted one's statistics.
// - 3D: a cylinder of five hexahedra whose mantle is bound to the mantle
//   of a solid CAD cylinder: refined once and twice, the volume of the
//   prism of 8 and 16 sides (to 1e-6), as with the built-in cylinder
//   binding (the solid's end caps, nearer to the midpoints of the rim's
//   edges, would draw those onto the caps: 1.31 instead of 1.41). The end
//   caps bound too, first: the rim's 8 edges follow the mantle, the later
//   binding, and the run names the edges the two tags share.
// - Bad input: a tag that is not on the boundary, a centre that the tag's
//   faces are not around, a cylinder in 2D, an item that is no binding; a
//   CAD file that does not exist, is a folder, is no IGES or STEP, cannot
//   be read, or whose curve the tag is not on (a circle of radius 2, or
//   the file declared in mm without its scale), a scale of 0 and one that
//   is no number.

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

  /// Copies the CAD file @p name of tests/cad (exact circles, see its
  /// README.md) to the working directory, on rank 0.
  void
  copy_cad_file(const std::string &name)
  {
    if (testing::this_rank() == 0)
      std::filesystem::copy_file(
        std::string(DYNCONTACT_SOURCE_DIR) + "/tests/cad/" + name,
        name,
        std::filesystem::copy_options::overwrite_existing);
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
  const double     exact_adapted =
    2. * std::sqrt(2.) +
    6. * 0.5 * (2. * std::sin(M_PI / 8.) - std::sin(M_PI / 4.));
  log() << "adaptive: cells " << adapted.column("cells").front() << " -> "
        << adapted.column("cells").back() << ", area bound to the circle "
        << fmt(area_of(adapted), 7) << " (exact " << fmt(exact_adapted, 7)
        << "), not bound " << fmt(area_of(unadapted), 7) << ": "
        << check(std::abs(area_of(adapted) - exact_adapted) < 1e-10 &&
                 std::abs(area_of(unadapted) - 2.) < 1e-10)
        << "\n";

  // 3. a checkpoint after the adaptation, resumed
  const auto resumed_difference = [&](const std::string &binding,
                                      const Statistics  &uninterrupted) {
    const std::string checkpointed =
      adaptive_prm("results-resumed", binding) +
      "subsection Checkpointing\n  set Interval in steps = 2\nend\n";
    std::string first_half = checkpointed;
    first_half.replace(first_half.find("End time = 0.04"),
                       15,
                       "End time = 0.02");
    run(first_half);
    const Statistics resumed = run(
      checkpointed + "subsection Checkpointing\n  set Resume = true\nend\n");
    return statistics_difference(uninterrupted, resumed).first;
  };
  log() << "resumed after the adaptation: ends as the uninterrupted run "
           "(largest difference < 1e-10): "
        << check(resumed_difference(bound, adapted) < 1e-10) << "\n";

  // 4. the circle as a CAD curve, in m (STEP) and in mm (IGES), and in a
  // file whose declared unit (mm) is not that of its numbers (m)
  copy_cad_file("circle.step");
  copy_cad_file("circle_mm.iges");
  copy_cad_file("circle_unit_mm.step");
  for (const std::string cad : {"20: cad circle.step",
                                "20: cad circle_mm.iges",
                                "20: cad circle_unit_mm.step scale 1000"})
    {
      const std::string binding = "    set Manifolds = " + cad + "\n";
      bool              exact   = true;
      for (unsigned int k = 1; k <= 3; ++k)
        {
          const double n = 4 * std::pow(2., k);
          exact          = exact &&
                  std::abs(area_of(run(disc_prm("results-cad", binding) +
                                       "subsection Mesh\n  set Initial global "
                                       "refinements = " +
                                       std::to_string(k) + "\nend\n")) -
                           n / 2 * std::sin(2 * M_PI / n)) < 1e-6;
        }
      const Statistics cad_adapted = run(adaptive_prm("results-cad", binding));
      log() << cad << ": 1 to 3 global refinements the polygons' areas, "
            << "adaptive " << fmt(area_of(cad_adapted), 7) << " (exact "
            << fmt(exact_adapted, 7) << "), to 1e-6: "
            << check(exact &&
                     std::abs(area_of(cad_adapted) - exact_adapted) < 1e-6)
            << "\n";
      if (cad.find("step") != std::string::npos)
        log() << cad << ": resumed after the adaptation, ends as the "
              << "uninterrupted run (largest difference < 1e-10): "
              << check(resumed_difference(binding, cad_adapted) < 1e-10)
              << "\n";
    }

  // 5. 3D: the mantle of a solid cylinder from a CAD file; its end caps,
  // which the mesh's mantle tag does not cover, do not draw the new points
  // on the mantle's rim
  copy_cad_file("cylinder.step");
  copy_cad_file("cylinder.msh");
  for (unsigned int k = 1; k <= 2; ++k)
    {
      const auto volume = [&](const std::string &binding) {
        return -run("set Dimension = 3\nset Output directory = "
                    "results-cylinder\n" +
                    scene_prm("gmsh",
                              "    set Mesh file = cylinder.msh\n"
                              "    set Initial velocity of body 1 = 0, -1, 0\n"
                              "    set Manifolds = 11: " +
                                binding + "\n") +
                    "subsection Mesh\n  set Initial global refinements = " +
                    std::to_string(k) +
                    "\nend\nsubsection Time integration\n"
                    "  set Time step = 0.01\n  set End time = 0.01\nend\n"
                    "subsection Output\n  set Write vtu = false\nend\n")
                  .column("momentum_y")
                  .back();
      };
      const double n     = 4 * std::pow(2., k);
      const double exact = 2. * n / 2 * std::sin(2 * M_PI / n) * 0.25;
      const double cad   = volume("cad cylinder.step");
      log() << "3D, " << k << " global refinements: volume bound to the CAD "
            << "cylinder " << fmt(cad, 6) << " (prism of " << n << " sides "
            << fmt(exact, 6) << "; bound to the cylinder "
            << fmt(volume("cylinder 0, 0, 0 axis 1, 0, 0"), 6)
            << "): " << check(std::abs(cad - exact) < 1e-6) << "\n";
    }
  // the end caps bound too: the rim's edges follow the later binding, and
  // the run says so; listed first, the caps leave the rim to the mantle
  {
    const std::string file = "caps_first.prm";
    if (this_rank() == 0)
      std::ofstream(file)
        << "set Dimension = 3\nset Output directory = results-caps\n"
        << scene_prm("gmsh",
                     "    set Mesh file = cylinder.msh\n"
                     "    set Initial velocity of body 1 = 0, -1, 0\n"
                     "    set Manifolds = 12: cad cylinder.step; 11: cad "
                     "cylinder.step\n")
        << "subsection Mesh\n  set Initial global refinements = 1\nend\n"
        << "subsection Time integration\n  set Time step = 0.01\n"
        << "  set End time = 0.01\nend\n"
        << "subsection Output\n  set Write vtu = false\nend\n";
    MPI_Barrier(MPI_COMM_WORLD);
    const Outcome outcome    = run_in_process(file);
    const double  caps_first = -read_statistics("results-caps/statistics.tsv")
                                 .column("momentum_y")
                                 .back();
    log() << "3D, the end caps bound first: volume " << fmt(caps_first, 6)
          << " (prism 1.41421), and the shared edges named: "
          << check(outcome.status == 0 &&
                   std::abs(caps_first - 2. * 4 * std::sin(M_PI / 4) * 0.25) <
                     1e-6 &&
                   outcome.text.find("binds tags 11 and 12, whose faces "
                                     "share 8 edges: new points on them "
                                     "follow tag 11") != std::string::npos)
          << "\n";
  }

  // 6. bad input
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"    set Manifolds = 21: sphere 0, 1.05\n",
     "binds tag 21, but the mesh file"},
    {"    set Manifolds = 20: sphere 0, 0\n", "the tag is not on this sphere"},
    {"    set Manifolds = 20: cylinder 0, 0, 0 axis 0, 0, 1\n",
     "In 2D a cylinder's section is a circle"},
    {"    set Manifolds = 20 sphere 0, 1.05\n", "is no 'tag: sphere x, y'"},
    {"    set Manifolds = 20: cad none.step\n",
     "the CAD file 'none.step' does not exist"},
    {"    set Manifolds = 20: cad disc.msh\n",
     "must be IGES (.iges, .igs) or STEP"},
    {"    set Manifolds = 20: cad garbage.step\n",
     "OpenCASCADE cannot read the CAD file"},
    {"    set Manifolds = 20: cad wide.step\n", "the tag is not on it"},
    {"    set Manifolds = 20: cad circle_unit_mm.step\n",
     "the tag is not on it"},
    {"    set Manifolds = 20: cad circle.step scale 0\n",
     "the scale must lie in (0, 1e15]"},
    {"    set Manifolds = 20: cad circle.step scale 1 m\n",
     "the scale '1 m' is no number"},
    {"    set Manifolds = 20: cad folder.step\n", "is no regular file"}};
  copy_cad_file("wide.step");
  if (this_rank() == 0)
    {
      std::ofstream("garbage.step") << "no STEP file\n";
      std::filesystem::create_directories("folder.step");
    }
  MPI_Barrier(MPI_COMM_WORLD);
  for (const auto &[entry, fragment] : cases)
    log() << "refused, naming the binding: "
          << entry.substr(4, entry.size() - 5) << ": "
          << check(error_of(disc_prm("results-bad", entry)).find(fragment) !=
                   std::string::npos)
          << "\n";
}
