#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/bar_impact.h>
#include <dyncontact/scenes/two_bars.h>

#include <cmath>

namespace dyncontact
{
  template <int dim>
  void
  TwoBars<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Two bars");
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
                      "Initial speed v0 of each bar towards the other, in "
                      "m/s (>= 0).");
    prm.declare_entry("Initial gap",
                      "0.1",
                      Patterns::Double(0., 1e9),
                      "Distance g0 of each bar's contact end from the "
                      "mid-plane x = 0, in m (>= 0; the bars are 2 g0 "
                      "apart).");
    prm.declare_entry("Cells along length",
                      "40",
                      Patterns::Integer(1),
                      "Coarse cells along the first bar (before global "
                      "refinement).");
    prm.declare_entry("Cells along length of body 2",
                      "0",
                      Patterns::Integer(0),
                      "Coarse cells along the second bar; 0 = as "
                      "many as along the first.");
    prm.declare_entry("Cells across",
                      "0",
                      Patterns::Integer(0),
                      "Coarse cells across the height of the first "
                      "bar; 0 = from the aspect ratio (at least one).");
    prm.declare_entry("Cells across body 2",
                      "0",
                      Patterns::Integer(0),
                      "Coarse cells across the height of the "
                      "second bar; 0 = as many as across the first. Different "
                      "numbers make non-matching meshes at the interface.");
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  void
  TwoBars<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Two bars");
    length          = prm.get_double("Length");
    height          = prm.get_double("Height");
    impact_velocity = prm.get_double("Impact velocity");
    initial_gap     = prm.get_double("Initial gap");
    cells_along[0]  = prm.get_integer("Cells along length");
    cells_along[1]  = prm.get_integer("Cells along length of body 2");
    cells_across[0] = prm.get_integer("Cells across");
    cells_across[1] = prm.get_integer("Cells across body 2");
    prm.leave_subsection();
    prm.leave_subsection();
    if (cells_along[1] == 0)
      cells_along[1] = cells_along[0];
    if (cells_across[0] == 0)
      cells_across[0] =
        std::max<unsigned int>(1,
                               std::lround(cells_along[0] * height / length));
    if (cells_across[1] == 0)
      cells_across[1] = cells_across[0];

    check_in_range(length, 1e-9, 1e9, "Scene/Two bars/Length", "m");
    check_in_range(height, 1e-9, 1e9, "Scene/Two bars/Height", "m");
    check_in_range(
      impact_velocity, 0., 1e9, "Scene/Two bars/Impact velocity", "m/s");
    check_in_range(initial_gap, 0., 1e9, "Scene/Two bars/Initial gap", "m");
    for (unsigned int b = 0; b < 2; ++b)
      check_cell_sides(length / cells_along[b],
                       height / cells_across[b],
                       "Scene/Two bars (bar " + std::to_string(b + 1) + ")");
  }



  template <int dim>
  double
  TwoBars<dim>::n_coarse_cells() const
  {
    return double(cells_along[0]) * std::pow(double(cells_across[0]), dim - 1) +
           double(cells_along[1]) * std::pow(double(cells_across[1]), dim - 1);
  }



  template <int dim>
  void
  TwoBars<dim>::create_coarse_mesh(Triangulation<dim, dim> &tria) const
  {
    std::array<Triangulation<dim, dim>, 2> bars;
    for (unsigned int b = 0; b < 2; ++b)
      {
        std::vector<unsigned int> repetitions(dim, cells_across[b]);
        repetitions[0] = cells_along[b];
        Point<dim> lower, upper;
        for (unsigned int d = 1; d < dim; ++d)
          upper[d] = height;
        lower[0] = (b == 0) ? -initial_gap - length : initial_gap;
        upper[0] = (b == 0) ? -initial_gap : initial_gap + length;
        GridGenerator::subdivided_hyper_rectangle(bars[b],
                                                  repetitions,
                                                  lower,
                                                  upper);
        // contact faces: bar 1's end x = -g0 (id 1), bar 2's x = g0 (id 2)
        for (const auto &cell : bars[b].active_cell_iterators())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                std::abs(cell->face(f)->center()[0] -
                         (b == 0 ? -initial_gap : initial_gap)) <
                  1e-10 * length)
              cell->face(f)->set_boundary_id(b + 1);
      }
    merge_bodies<dim>({&bars[0], &bars[1]}, tria);
  }



  template <int dim>
  std::vector<ContactPair>
  TwoBars<dim>::contact_pairs() const
  {
    ContactPair pair;
    pair.first_side    = {1};
    pair.second_side   = {2};
    pair.search_radius = 2. * initial_gap + height;

    return {pair};
  }



  template <int dim>
  Tensor<1, dim>
  TwoBars<dim>::initial_velocity(const Point<dim>  &x,
                                 const unsigned int body) const
  {
    Tensor<1, dim> v;
    (void)x;
    v[0] = (body == 0) ? impact_velocity : -impact_velocity;
    return v;
  }



  template <int dim>
  bool
  TwoBars<dim>::has_exact_solution() const
  {
    const Material &mat = this->material(0);
    return this->one_material() && mat.poissons_ratio == 0. &&
           !mat.is_viscous() && impact_velocity > 0.;
  }



  template <int dim>
  ExactValues<dim>
  TwoBars<dim>::exact_solution(const Point<dim> &x, const double t) const
  {
    // bar 2 is the bar impact in xi = x - g0 with the wall at x = 0; bar 1
    // its mirror image
    const double        sign = (x[0] < 0.) ? -1. : 1.;
    const BarSolution1D bar =
      exact_bar_impact_1d(sign * x[0] - initial_gap,
                          t,
                          length,
                          this->material(0).bar_wave_speed(),
                          impact_velocity,
                          initial_gap);
    ExactValues<dim> values;
    values.displacement[0]             = sign * bar.displacement;
    values.velocity[0]                 = sign * bar.velocity;
    values.displacement_gradient[0][0] = bar.strain;
    return values;
  }


  DYNCONTACT_REGISTER_SCENE(TwoBars,
                            "two bars",
                            "two bars meeting head-on, with an exact "
                            "solution")
} // namespace dyncontact
