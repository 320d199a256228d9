// The contact zone that 'Contact zone refinements' refines for a drop
// (a review of the trust in the results): sized from Hertz's impact, not from
// the static load (zero for a drop, which refined only the cells at the first
// contact point). HertzScene::impact_contact_size() against values computed
// here another way: in 3D Hertz's closed form a = sqrt(R alpha_max), alpha_max
// = (15 m v^2 / (16 E* sqrt(R)))^(2/5); in 2D the force P whose work P dalpha
// (the indentation alpha(P) of a cylinder on a half-space, differentiated and
// integrated numerically here) equals 1/2 m v^2, and b = sqrt(4 P R / (pi E*)).
// Then the mesh: with one refinement of the zone the refined cells reach out
// to 1.5 a + g0 from the first contact point (at least 0.8 times, and not
// beyond by more than a coarse cell); without a drop velocity (the static size,
// zero without a load) they reach less than half as far.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <dyncontact/core/parameter_file.h>
#include <dyncontact/scenes/hertz.h>
#include <dyncontact/scenes/interface.h>

#include <cmath>
#include <iomanip>

#include "tests.h"

using namespace dyncontact;
using testing::check;
using testing::log;

namespace
{
  // 2D: the force whose work over the indentation equals the energy
  double
  cylinder_force(const double energy, const double E, const double R)
  {
    const auto alpha = [&](const double P) {
      const double b = std::sqrt(4. * P * R / (M_PI * E));
      return P / (M_PI * E) * (2. * std::log(4. * R / b) - 1.);
    };
    const auto work = [&](const double P) {
      // midpoint rule in p of p alpha'(p), alpha' by central differences
      const unsigned int n = 20000;
      double             w = 0.;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double p = (i + 0.5) * P / n, d = 1e-4 * p;
          w += p * (alpha(p + d) - alpha(p - d)) / (2. * d) * P / n;
        }
      return w;
    };
    double low = 0., high = 1.;
    while (work(high) < energy)
      high *= 2.;
    for (unsigned int i = 0; i < 50; ++i)
      (work(0.5 * (low + high)) < energy ? low : high) = 0.5 * (low + high);
    return 0.5 * (low + high);
  }
} // namespace

template <int dim>
double
check_zone(const double drop_velocity)
{
  const double      R = 1., v = drop_velocity, g0 = 0.01, nu = 0.3;
  const double      E    = (dim == 2) ? 1. : 100.;
  const std::string name = (dim == 2) ? "hertz" : "ball on block";
  const std::string sub  = (dim == 2) ? "Hertz" : "Ball on block";

  ParameterHandler prm;
  declare_all_parameters(prm);
  std::ostringstream text;
  text << "set Dimension = " << dim << "\n"
       << "subsection Scene\n  set Name = " << name << "\n  subsection " << sub
       << "\n    set Load = 0\n    set Drop velocity = " << v
       << "\n    set Initial gap = " << g0
       << "\n    set Contact zone refinements = 1\n  end\nend\n"
       << "subsection Material\n  set Young's modulus = " << E
       << "\n  set Poisson's ratio = " << nu << "\n  set Density = 1\nend\n"
       << "subsection Material of body 2\n  set Young's modulus = " << E
       << "\n  set Poisson's ratio = " << nu << "\nend\n";
  prm.parse_input_from_string(text.str());
  const auto scene =
    create_scene<dim>(prm, ".", prm.get_integer("Polynomial degree"), true);
  const auto &hertz = dynamic_cast<const HertzScene<dim> &>(*scene);

  const double E_star = E / (2. * (1. - nu * nu));
  const double mass =
    (dim == 2) ? 0.5 * M_PI * R * R : 2. / 3. * M_PI * R * R * R;
  const double energy   = 0.5 * mass * v * v;
  double       expected = 0.;
  if (v > 0. && dim == 3)
    expected = std::sqrt(
      R * std::pow(15. * mass * v * v / (16. * E_star * std::sqrt(R)), 0.4));
  else if (v > 0.)
    expected =
      std::sqrt(4. * cylinder_force(energy, E_star, R) * R / (M_PI * E_star));
  const double size = hertz.impact_contact_size();
  log() << std::fixed << std::setprecision(1) << dim << "D, v = " << v
        << " m/s: impact contact size " << std::setprecision(4) << size
        << " m, computed here " << expected
        << " m: " << check(std::abs(size - expected) <= 1e-4 * (1. + expected))
        << "\n";

  parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
  build_mesh(*scene, triangulation, 2, 1, false);
  // how far from the first contact point (the origin) the cells refined
  // by the zone reach, and the size of the unrefined cells there
  double reach = 0., coarse = 0.;
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->level() > 2)
      {
        reach  = std::max(reach, cell->center().norm());
        coarse = std::max(coarse, 2. * cell->diameter());
      }
  const double zone = 1.5 * expected + g0;
  if (v > 0.)
    log() << "  refined cells reach " << std::setprecision(2) << reach
          << " m, zone 1.5 a + g0 = " << zone
          << " m: " << check(reach >= 0.8 * zone && reach <= zone + coarse)
          << "\n";
  return reach;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // without a drop velocity the zone is the static one (zero without a
  // load): the cells at the first contact point
  const double reach_2d = check_zone<2>(0.1), static_2d = check_zone<2>(0.);
  log() << "  without a drop the refined cells reach " << std::setprecision(2)
        << static_2d
        << " m: less than half as far: " << check(static_2d < 0.5 * reach_2d)
        << "\n";
  const double reach_3d = check_zone<3>(0.1), static_3d = check_zone<3>(0.);
  log() << "  without a drop the refined cells reach " << std::setprecision(2)
        << static_3d
        << " m: less than half as far: " << check(static_3d < 0.5 * reach_3d)
        << "\n";
}
