// The loads of the Gmsh scene, each against a closed-form solution, with a
// density, a modulus, a gravity and a traction away from 1 and from each
// other (rho = 3 kg/m^3, E = 7 Pa, nu = 0, g = 2.5 m/s^2, t = 0.4 Pa), on a
// block [0, 1.2] x [0, 0.5] of 6 x 4 cells (bottom tag 10, top tag 11):
//  - free fall under Gravity = (0, -g) (N-CS++, no support): the mean
//    displacement is -g t^2 / 2 and the momentum -rho V g t at every step
//    (the trapezoidal rule integrates a constant acceleration exactly), so
//    that a body force of the wrong sign or a mass without its density
//    fails;
//  - the block clamped at its bottom under its own weight (static, FE_Q(2),
//    which holds the exact u_y = -rho g (H y - y^2 / 2) / E): mean
//    displacement -rho g H^2 / (3 E), potential energy
//    -(rho g)^2 W H^3 / (6 E);
//  - the block clamped at its bottom, pulled at its top by the Neumann
//    traction (0, t) (static, FE_Q(1), exact u_y = t y / E): mean
//    displacement t H / (2 E), potential energy -t^2 W H / (2 E);
//  - the block standing on the rigid obstacle y <= 0 under its weight,
//    damped by its viscosity (mu_v = 1 Pa s), from rest: at T = 4 s the
//    contact force carries the weight rho g W H (per unit depth) to 0.1 %
//    and the block is at rest.
// Also on two MPI ranks (gmsh_loads.mpirun=2) with the same output.

#include "tests.h"

namespace
{
  const double rho = 3., E = 7., g = 2.5, traction = 0.4, W = 1.2, H = 0.5;

  /// The input of a run on the block with @p entries in Scene/Gmsh and
  /// @p more at the top level.
  std::string
  block_prm(const std::string &name,
            const std::string &entries,
            const std::string &more)
  {
    std::ostringstream s;
    s << std::setprecision(17) << "set Dimension = 2\n"
      << "set Output directory = results-" << name << "\n"
      << testing::scene_prm("gmsh",
                            "    set Mesh file = block.msh\n"
                            "    set Bodies = 1\n" +
                              entries)
      << "subsection Material\n  set Young's modulus = " << E
      << "\n  set Poisson's ratio = 0\n  set Density = " << rho << "\nend\n"
      << "subsection Output\n  set Write vtu = false\nend\n"
      << more;
    return s.str();
  }

  /// The largest of |a_i - b_i| / @p scale.
  double
  worst(const std::vector<double> &a,
        const std::vector<double> &b,
        const double               scale)
  {
    double w = a.size() == b.size() ? 0. : 1e300;
    for (unsigned int i = 0; i < a.size() && i < b.size(); ++i)
      w = std::max(w, std::abs(a[i] - b[i]) / scale);
    return w;
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  write_block_msh("block.msh", {Block{0., W, 0., H, 6, 4, 1, 10, 11}});
  const double      V       = W * H;
  const std::string gravity = "    set Gravity = 0, " + fmt(-g, 17) + "\n";
  const std::string static_scheme =
    "subsection Time integration\n  set Scheme = static\nend\n";

  // free fall
  {
    const Statistics s =
      run(block_prm("fall",
                    gravity,
                    "subsection Time integration\n  set Scheme = N-CS++\n"
                    "  set Time step = 0.01\n  set End time = 0.2\nend\n"));
    const auto          t = s.column("time");
    std::vector<double> fall, momentum;
    for (const double ti : t)
      {
        fall.push_back(-0.5 * g * ti * ti);
        momentum.push_back(-rho * V * g * ti);
      }
    const double d_error =
      worst(s.column("mean_displacement_y"), fall, 0.5 * g * 0.04);
    const double p_error =
      worst(s.column("momentum_y"), momentum, rho * V * g * 0.2);
    log() << "free fall under gravity, " << t.size() - 1
          << " steps: mean displacement -g t^2/2 (1e-9): "
          << check(d_error <= 1e-9 && t.size() == 21)
          << ", momentum -rho V g t (1e-9): " << check(p_error <= 1e-9)
          << ", none along x: "
          << check(max_of(s.column("mean_displacement_x")) <= 1e-12 &&
                   min_of(s.column("mean_displacement_x")) >= -1e-12)
          << "\n";
  }

  // its own weight, clamped at the bottom (FE_Q(2) holds the exact
  // solution)
  {
    const Statistics s =
      run(block_prm("weight",
                    gravity + "    set Dirichlet tags = 10\n",
                    static_scheme + "set Polynomial degree = 2\n"));
    const double mean     = s.column("mean_displacement_y").back();
    const double energy   = s.column("energy_elastic").back();
    const double mean_0   = -rho * g * H * H / (3. * E);
    const double energy_0 = -(rho * g) * (rho * g) * W * H * H * H / (6. * E);
    log() << "own weight, clamped below (static, p = 2): mean displacement "
          << fmt(mean, 6) << " (exact " << fmt(mean_0, 6)
          << "): " << check(std::abs(mean / mean_0 - 1.) <= 1e-8)
          << ", potential energy " << fmt(energy, 6) << " (exact "
          << fmt(energy_0, 6)
          << "): " << check(std::abs(energy / energy_0 - 1.) <= 1e-8) << "\n";
  }

  // a traction on the top, clamped at the bottom
  {
    const Statistics s        = run(block_prm("traction",
                                       "    set Dirichlet tags = 10\n"
                                              "    set Neumann tags = 11\n"
                                              "    set Neumann traction = 0, " +
                                         fmt(traction, 17) + "\n",
                                       static_scheme));
    const double     mean     = s.column("mean_displacement_y").back();
    const double     energy   = s.column("energy_elastic").back();
    const double     mean_0   = traction * H / (2. * E);
    const double     energy_0 = -traction * traction * W * H / (2. * E);
    log() << "Neumann traction on the top, clamped below (static, p = 1): "
             "mean displacement "
          << fmt(mean, 6) << " (exact " << fmt(mean_0, 6)
          << "): " << check(std::abs(mean / mean_0 - 1.) <= 1e-8)
          << ", potential energy " << fmt(energy, 6) << " (exact "
          << fmt(energy_0, 6)
          << "): " << check(std::abs(energy / energy_0 - 1.) <= 1e-8) << "\n";
  }

  // standing on the rigid obstacle
  {
    const Statistics s = run(
      block_prm("standing",
                gravity + "    set Contact tags = 10\n"
                          "    set Contact pairs = 1 : obstacle\n"
                          "    set Obstacle point = 0, 0\n"
                          "    set Obstacle normal = 0, 1\n",
                "subsection Material\n  set Viscous shear modulus = 1\nend\n"
                "subsection Time integration\n  set Scheme = N-CS++\n"
                "  set Time step = 0.02\n  set End time = 4\nend\n"));
    const double force  = s.column("contact_force").back();
    const double weight = rho * g * V;
    const double speed =
      std::abs(s.column("momentum_y").back()) / (rho * V * std::sqrt(E / rho));
    log() << "standing on the obstacle under its weight (viscous, T = 4 s): "
             "contact force "
          << fmt(force, 4) << " N/m (rho g V = " << fmt(weight, 4)
          << "): " << check(std::abs(force / weight - 1.) <= 1e-3)
          << ", at rest (mean velocity below 1e-4 c): " << check(speed <= 1e-4)
          << ", no penetration: "
          << check(max_of(s.column("max_penetration")) <= 1e-12) << "\n";
  }
}
