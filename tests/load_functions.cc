// Loads as functions of x and t (Scene/Gmsh/Pressures, Body force, Neumann
// tractions with expressions), against exact answers:
//
// 1. A column [0, 1] x [0, 2] on rollers (bottom: y fixed, sides: x fixed,
//    a state of uniaxial strain), its top pressed by p(t) = p0 min(t/0.5, 1),
//    viscous: it comes to rest at the static solution u_y = -p0 y / (lambda
//    + 2 mu), which linear elements represent exactly (mean -p0 / (lambda +
//    2 mu)); E + W_visc - W_load stays E(0) = 0 within round-off, which a
//    wrong sign or time of the load's work breaks. The same load as the
//    traction (0, -p(t)) of Neumann tractions gives the same run.
// 2. A free block under the body force (0, -c t): its momentum is
//    -c |V| t^2 / 2 exactly (the step's load is the trapezoidal mean
//    (f^n + f^{n+1}) / 2; f^n alone would miss it by tau / t = 10 %); with
//    a traction of x alone on its top beside it (assembled once per mesh),
//    its momentum along x grows by that traction's force exactly.
// 3. Symmetry: a block dropped onto the rigid obstacle under a pressure
//    symmetric in x, modelled whole ([-1, 1] wide) and as the half [0, 1]
//    on a roller at x = 0: the half has half of every energy and the same
//    mean vertical displacement at every step.
// 4. Bad input is refused naming the entry.

#include <cmath>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  const std::string material = "subsection Material\n"
                               "  set Young's modulus = 100\n"
                               "  set Poisson's ratio = 0.3\n"
                               "  set Viscous shear modulus = 5\n"
                               "  set Viscous Lame parameter = 5\n"
                               "end\n";
  const auto        prm      = [](const std::string &mesh,
                      const std::string &entries,
                      const std::string &end_time,
                      const std::string &more) {
    return "set Dimension = 2\nset Output directory = results-loads\n" +
           scene_prm("gmsh", "    set Mesh file = " + mesh + "\n" + entries) +
           more +
           "subsection Time integration\n  set Scheme = N-CS++\n"
                       "  set Time step = 0.01\n  set End time = " +
           end_time +
           "\nend\n"
                       "subsection Output\n  set Write vtu = false\nend\n";
  };

  // 1. the column under a ramped pressure
  write_block_msh("column.msh", {{0, 1, 0, 2, 4, 8, 1, 10, 11, 12, 13}});
  const std::string supports = "    set Dirichlet tags = 10: y, 12: x, 13: x\n"
                               "    set Function constants = p0 = 1\n";
  const double      lambda = 100. * 0.3 / (1.3 * 0.4), mu = 100. / 2.6;
  const double      exact = -1. / (lambda + 2. * mu);
  for (const std::string load :
       {"    set Pressures = 11: p0*min(t/0.5, 1)\n",
        "    set Neumann tractions = 11: 0, -p0*min(t/0.5, 1)\n"})
    {
      const Statistics s =
        run(tight_steps() + prm("column.msh", supports + load, "3", material));
      const double mean    = s.column("mean_displacement_y").back();
      double       balance = 0.;
      for (const double b : s.column("energy_balance"))
        balance = std::max(balance, std::abs(b));
      log() << load.substr(8, load.find('=') - 9) << ": mean u_y at t = 3 s "
            << fmt(mean, 6) << ", static " << fmt(exact, 6)
            << ", W_load = " << fmt(s.column("work_load_change").back(), 4)
            << ", largest |energy_balance| below 1e-14: "
            << check(std::abs(mean / exact - 1.) < 1e-5 && balance < 1e-14)
            << "\n";
    }

  // 2. a free block under a body force linear in t
  write_block_msh("free.msh", {{0, 1, 0, 0.5, 4, 2, 1, 10, 11}});
  {
    const Statistics s =
      run(tight_steps() +
          prm("free.msh",
              "    set Body force = 0; -c*t\n"
              "    set Function constants = c = 3\n",
              "0.1",
              "subsection Material\n  set Young's modulus = 100\nend\n"));
    const double t = s.column("time").back();
    const double p = s.column("momentum_y").back();
    log() << "free block: momentum_y at t = " << fmt(t) << " s " << fmt(p, 6)
          << ", exact -c V t^2/2 = " << fmt(-3. * 0.5 * t * t / 2., 6) << ": "
          << check(std::abs(p + 3. * 0.5 * t * t / 2.) < 1e-12) << "\n";
    // with a traction of x alone on its top beside it (assembled once per
    // mesh, the body force at every step): the force int q (1 + x) dx =
    // 1.5 q along x as well
    const Statistics both =
      run(tight_steps() +
          prm("free.msh",
              "    set Body force = 0; -c*t\n"
              "    set Neumann tractions = 11: q*(1 + x), 0\n"
              "    set Function constants = c = 3, q = 2\n",
              "0.1",
              "subsection Material\n  set Young's modulus = 100\nend\n"));
    const double px = both.column("momentum_x").back();
    const double py = both.column("momentum_y").back();
    log() << "with a traction q (1 + x) on its top: momentum_x " << fmt(px, 6)
          << ", exact 1.5 q t = " << fmt(3. * t, 6) << ", momentum_y "
          << fmt(py, 6) << ": "
          << check(std::abs(px - 3. * t) < 1e-12 &&
                   std::abs(py + 3. * 0.5 * t * t / 2.) < 1e-12)
          << "\n";
  }

  // 3. the whole block and its half on a roller
  write_block_msh("whole.msh", {{-1, 1, 0.02, 1.02, 8, 4, 1, 10, 11, 12, 13}});
  write_block_msh("half.msh", {{0, 1, 0.02, 1.02, 4, 4, 1, 10, 11, 12, 13}});
  const std::string drop =
    "    set Bodies = 1\n    set Contact tags = 10\n"
    "    set Contact pairs = 1 : obstacle\n"
    "    set Obstacle point = 0, 0\n    set Obstacle normal = 0, 1\n"
    "    set Initial velocity = 0; -1\n"
    "    set Pressures = 11: 5*(1 + x^2)*min(t/0.05, 1)\n";
  const Statistics whole =
    run(tight_steps() + prm("whole.msh", drop, "0.3", material));
  const Statistics half =
    run(tight_steps() + prm("half.msh",
                            drop + "    set Dirichlet tags = 12: x\n",
                            "0.3",
                            material));
  double largest = 0.;
  for (const std::string column : {"energy_kinetic",
                                   "energy_elastic",
                                   "dissipation_viscous",
                                   "work_load_change",
                                   "mean_displacement_y"})
    {
      const double factor = column == "mean_displacement_y" ? 1. : 2.;
      const auto   a = whole.column(column), b = half.column(column);
      double       scale = 1e-300, d = 0.;
      for (unsigned int r = 0; r < a.size() && r < b.size(); ++r)
        {
          scale = std::max(scale, std::abs(a[r]));
          d     = std::max(d, std::abs(a[r] - factor * b[r]));
        }
      largest = std::max(largest, a.size() == b.size() ? d / scale : 1.);
    }
  const auto interval = contact_interval(half);
  log() << "half model: contact from t = " << fmt(interval.first)
        << " s; energies are half the whole model's and the mean u_y the "
           "same within 1e-8 at every step: "
        << check(interval.first > 0. && largest < 1e-8) << "\n";

  // 4. bad input
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"    set Pressures = 11: 1 +* t\n", "Scene/Gmsh/Pressures (tag 11)"},
    {"    set Body force = 0; q*t\n", "Scene/Gmsh/Body force"},
    {"    set Body force = 0\n", "components separated by ';'"},
    {"    set Pressures = 11: 1, 2\n", "a pressure is a scalar"},
    {"    set Neumann tractions = 11: t, 0, 1\n", "a 2D mesh needs 2"},
    {"    set Pressures = 11: t\n    set Neumann tags = 11\n",
     "tag 11 has a traction already"},
    {"    set Pressures = 10: t\n", "is in Dirichlet tags and carries a load"},
    {"    set Pressures = 14: t\n", "Scene/Gmsh/Pressures: the mesh file"},
    {"    set Pressures = 11:\n", "must be one expression"},
    {"    set Pressures = 11: pi\n    set Function constants = pi = 3\n",
     "names a constant 'pi', which is predefined"}};
  for (const auto &[entries, fragment] : cases)
    {
      const std::string message =
        error_of(prm("column.msh", supports + entries, "0.1", material));
      log() << "refused: " << entries.substr(8, entries.find('\n') - 8) << ": "
            << check(message.find(fragment) != std::string::npos) << "\n";
      if (message.find(fragment) == std::string::npos)
        log() << "  (" << message << ")\n";
    }
}
