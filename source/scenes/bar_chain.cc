#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/bar_chain.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
  namespace
  {
    /// The free-free rod [0, l_rod] with initial displacement 0 and initial
    /// velocity v0 on [0, l_striker), 0 elsewhere, at (y, s) by
    /// d'Alembert's formula with the even 2 l_rod-periodic extension of the
    /// initial velocity: u = (V(y + c s) - V(y - c s)) / 2c, V its
    /// antiderivative.
    struct FreeRod
    {
      double l_rod, l_striker, c, v0;

      double
      velocity_0(const double z) const
      {
        const double period = 2. * l_rod;
        const double r      = z - period * std::floor(z / period);
        return (r < l_striker || r > period - l_striker) ? v0 : 0.;
      }

      double
      integral_0(const double z) const
      {
        const double period = 2. * l_rod;
        const double n      = std::floor(z / period);
        const double r      = z - period * n;
        return n * 2. * v0 * l_striker + v0 * std::min(r, l_striker) +
               v0 * std::max(0., r - (period - l_striker));
      }

      /// Displacement, velocity and strain at y and time s.
      std::array<double, 3>
      operator()(const double y, const double s) const
      {
        const double a = y + c * s, b = y - c * s;
        return {{(integral_0(a) - integral_0(b)) / (2. * c),
                 (velocity_0(a) + velocity_0(b)) / 2.,
                 (velocity_0(a) - velocity_0(b)) / (2. * c)}};
      }
    };
  } // namespace



  template <int dim>
  void
  BarChain<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Bar chain");
    prm.declare_entry("Bars in the chain",
                      "3",
                      Patterns::Integer(1, 50),
                      "Number K of bars at rest in the chain (1 to 50); with "
                      "the striker the scene has K + 1 bodies and K contact "
                      "pairs.");
    prm.declare_entry("Length",
                      "1",
                      Patterns::Double(1e-9, 1e9),
                      "Length L of each bar, in m (> 0).");
    prm.declare_entry("Height",
                      "0.1",
                      Patterns::Double(1e-9, 1e9),
                      "Height (and, in 3D, width) of the bars, in m (> 0).");
    prm.declare_entry("Impact velocity",
                      "1",
                      Patterns::Double(0., 1e9),
                      "Initial speed v0 of the striker towards the chain, in "
                      "m/s (>= 0).");
    prm.declare_entry("Initial gap",
                      "0.1",
                      Patterns::Double(0., 1e9),
                      "Distance g0 between the striker and the first bar of "
                      "the chain, in m (>= 0); the bars of the chain touch.");
    prm.declare_entry("Cells along length",
                      "20",
                      Patterns::Integer(1),
                      "Coarse cells along each bar (before global "
                      "refinement).");
    prm.declare_entry("Cells across",
                      "0",
                      Patterns::Integer(0),
                      "Coarse cells across the height of each bar; 0 = from "
                      "the aspect ratio (at least one).");
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  void
  BarChain<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Bar chain");
    n_chain         = prm.get_integer("Bars in the chain");
    length          = prm.get_double("Length");
    height          = prm.get_double("Height");
    impact_velocity = prm.get_double("Impact velocity");
    initial_gap     = prm.get_double("Initial gap");
    cells_along     = prm.get_integer("Cells along length");
    cells_across    = prm.get_integer("Cells across");
    prm.leave_subsection();
    prm.leave_subsection();
    if (cells_across == 0)
      cells_across =
        std::max<unsigned int>(1, std::lround(cells_along * height / length));

    check_in_range(length, 1e-9, 1e9, "Scene/Bar chain/Length", "m");
    check_in_range(height, 1e-9, 1e9, "Scene/Bar chain/Height", "m");
    check_in_range(
      impact_velocity, 0., 1e9, "Scene/Bar chain/Impact velocity", "m/s");
    check_in_range(initial_gap, 0., 1e9, "Scene/Bar chain/Initial gap", "m");
    check_cell_sides(length / cells_along,
                     height / cells_across,
                     "Scene/Bar chain");
  }



  template <int dim>
  double
  BarChain<dim>::n_coarse_cells() const
  {
    return double(n_chain + 1) * cells_along *
           std::pow(double(cells_across), dim - 1);
  }



  template <int dim>
  void
  BarChain<dim>::create_coarse_mesh(Triangulation<dim, dim> &tria) const
  {
    std::vector<Triangulation<dim, dim>> bars(n_chain + 1);
    std::vector<unsigned int>            repetitions(dim, cells_across);
    repetitions[0] = cells_along;
    for (unsigned int b = 0; b <= n_chain; ++b)
      {
        Point<dim> lower, upper;
        for (unsigned int d = 1; d < dim; ++d)
          upper[d] = height;
        lower[0] = (b == 0) ? -initial_gap - length : (b - 1) * length;
        upper[0] = lower[0] + length;
        GridGenerator::subdivided_hyper_rectangle(bars[b],
                                                  repetitions,
                                                  lower,
                                                  upper);
        // the ends: left 2b + 1, right 2b + 2; the sides keep id 0
        for (const auto &cell : bars[b].active_cell_iterators())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              for (unsigned int end = 0; end < 2; ++end)
                if (std::abs(cell->face(f)->center()[0] -
                             (end == 0 ? lower[0] : upper[0])) < 1e-10 * length)
                  cell->face(f)->set_boundary_id(2 * b + 1 + end);
      }
    std::vector<const Triangulation<dim, dim> *> pointers;
    for (const auto &bar : bars)
      pointers.push_back(&bar);
    merge_bodies<dim>(pointers, tria);
  }



  template <int dim>
  std::vector<ContactPair>
  BarChain<dim>::contact_pairs() const
  {
    // pair i: the right end of bar i - 1 against the left end of bar i
    std::vector<ContactPair> pairs(n_chain);
    for (unsigned int i = 1; i <= n_chain; ++i)
      {
        ContactPair &pair  = pairs[i - 1];
        pair.first_side    = {types::boundary_id(2 * (i - 1) + 2)};
        pair.second_side   = {types::boundary_id(2 * i + 1)};
        pair.search_radius = (i == 1 ? initial_gap : 0.) + height;
      }
    return pairs;
  }



  template <int dim>
  Tensor<1, dim>
  BarChain<dim>::initial_velocity(const Point<dim> &,
                                  const unsigned int body) const
  {
    Tensor<1, dim> v;
    v[0] = (body == 0) ? impact_velocity : 0.;
    return v;
  }



  template <int dim>
  bool
  BarChain<dim>::has_exact_solution() const
  {
    const Material &mat = this->material(0);
    return this->one_material() && mat.poissons_ratio == 0. &&
           !mat.is_viscous() && impact_velocity > 0.;
  }



  template <int dim>
  ExactValues<dim>
  BarChain<dim>::exact_solution(const Point<dim> &x, const double t) const
  {
    // the striker and the chain as one rod y in [0, (K + 1) L], the striker
    // [0, L], from the impact t0 = g0/v0 on
    const double       L = length, v0 = impact_velocity;
    const double       c       = this->material(0).bar_wave_speed();
    const double       t0      = initial_gap / v0;
    const bool         striker = x[0] < 0.;
    const unsigned int bar =
      striker ? 0 :
                std::min<unsigned int>(n_chain,
                                       1 + static_cast<unsigned int>(
                                             std::max(0., x[0] / L)));
    const double y = striker ? x[0] + initial_gap + L : x[0] + L;

    double u = 0., v = 0., strain = 0.;
    if (t < t0)
      {
        if (striker)
          u = v0 * t, v = v0;
      }
    else
      {
        // each bar follows the rod until the pulse has passed it; the last
        // one leaves with v0
        const double freeze = (bar < n_chain ? bar + 2 : n_chain + 1) * L / c;
        const double s      = std::min(t - t0, freeze);
        const auto   rod    = FreeRod{(n_chain + 1) * L, L, c, v0}(y, s);
        u                   = rod[0] + (striker ? initial_gap : 0.);
        v                   = (t - t0 < freeze) ? rod[1] : 0.;
        strain              = (t - t0 < freeze) ? rod[2] : 0.;
        if (bar == n_chain && t - t0 >= freeze)
          u += v0 * (t - t0 - freeze), v = v0;
      }
    ExactValues<dim> values;
    values.displacement[0]             = u;
    values.velocity[0]                 = v;
    values.displacement_gradient[0][0] = strain;
    return values;
  }


  DYNCONTACT_REGISTER_SCENE(BarChain,
                            "bar chain",
                            "Newton's cradle of bars: a striker hits a chain "
                            "of bars at rest, with an exact solution")
} // namespace dyncontact
