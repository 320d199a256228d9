#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/bar_impact.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
  BarSolution1D
  exact_bar_impact_1d(const double x,
                      const double t,
                      const double length,
                      const double c,
                      const double v0,
                      const double g0)
  {
    const double s = t - g0 / v0;
    const double T = 2. * length / c;

    BarSolution1D bar{0., 0., 0.};
    if (s <= 0.)
      {
        bar.displacement = -v0 * t;
        bar.velocity     = -v0;
      }
    else if (s <= T)
      {
        // u = -g0 - v0 min(x/c, s, T - s)
        const double a = x / c, b = s, d = T - s;
        if (a <= b && a <= d)
          {
            bar.displacement = -g0 - v0 * a;
            bar.strain       = -v0 / c;
          }
        else if (b <= d)
          {
            bar.displacement = -g0 - v0 * b;
            bar.velocity     = -v0;
          }
        else
          {
            bar.displacement = -g0 - v0 * d;
            bar.velocity     = v0;
          }
      }
    else
      {
        bar.displacement = -g0 + v0 * (s - T);
        bar.velocity     = v0;
      }
    return bar;
  }



  template <int dim>
  void
  BarImpact<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Bar impact");
    prm.declare_entry("Length",
                      "1",
                      Patterns::Double(1e-9, 1e9),
                      "Length L of the bar along x, in m, 1e-9 to 1e9.");
    prm.declare_entry("Height",
                      "0.1",
                      Patterns::Double(1e-9, 1e9),
                      "Height (and, in 3D, width) of the bar, in "
                      "m, 1e-9 to 1e9, and at least 1/1000 of a cell's "
                      "length.");
    prm.declare_entry("Impact velocity",
                      "1",
                      Patterns::Double(0., 1e9),
                      "Initial speed v0 towards the wall, in m/s, "
                      "0 to 1e9 (0: the bar rests; it touches the wall only "
                      "if Initial gap <= 0 or a load pushes it).");
    prm.declare_entry("Initial gap",
                      "0.1",
                      Patterns::Double(-1e9, 1e9),
                      "Distance g0 between the bar's end x = 0 "
                      "and the wall at x = -g0, in m (negative: the bar "
                      "starts inside the wall; see "
                      "Contact/Initial penetration).");
    prm.declare_entry("Cells along length",
                      "40",
                      Patterns::Integer(1),
                      "Number of coarse cells along the bar "
                      "(before global refinement); the cells across follow "
                      "from the aspect ratio (at least one).");
    prm.declare_entry("Initial strain",
                      "0",
                      Patterns::Double(-1., 1.),
                      "A uniform initial axial strain eps0 (u0 = "
                      "eps0 x e_x, dimensionless, in (-1, 1]); nonzero values "
                      "make "
                      "the bar vibrate. The exact solution then follows from "
                      "d'Alembert's solution along the characteristics, but "
                      "the program does not compute it: no error norm is "
                      "reported. Cannot be combined with Fixed far end.");
    prm.declare_entry("Fixed far end",
                      "false",
                      Patterns::Bool(),
                      "Whether the end x = L is clamped "
                      "(homogeneous Dirichlet data, all components).");
    prm.declare_entry("Body force",
                      "0",
                      Patterns::Double(-1e15, 1e15),
                      "A constant body force density along the "
                      "bar's axis, in N/m^3; positive values point along "
                      "+e_x, away from the wall (which is at x = -g0).");
    prm.declare_entry("End traction",
                      "0",
                      Patterns::Double(-1e15, 1e15),
                      "A constant traction along the bar's axis "
                      "on the end x = 0 (a Neumann boundary that is also "
                      "the contact boundary), in Pa; positive values point "
                      "along +e_x, away from the wall (pulling the end off "
                      "it), negative values press it towards the wall.");
    prm.declare_entry("Rotation angle",
                      "0",
                      Patterns::Double(-360., 360.),
                      "The whole scene (bar, velocity, wall) is "
                      "rotated by this angle about the z axis, in degrees, so "
                      "that the wall normal need not be a coordinate axis.");
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  void
  BarImpact<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Bar impact");
    length             = prm.get_double("Length");
    height             = prm.get_double("Height");
    impact_velocity    = prm.get_double("Impact velocity");
    initial_gap        = prm.get_double("Initial gap");
    cells_along_length = prm.get_integer("Cells along length");
    initial_strain     = prm.get_double("Initial strain");
    fixed_far_end      = prm.get_bool("Fixed far end");
    axial_body_force   = prm.get_double("Body force");
    end_traction       = prm.get_double("End traction");
    angle              = prm.get_double("Rotation angle") * M_PI / 180.;
    prm.leave_subsection();
    prm.leave_subsection();

    const std::string section = "Scene/Bar impact/";
    check_in_range(length, 1e-9, 1e9, section + "Length", "m");
    check_in_range(height, 1e-9, 1e9, section + "Height", "m");
    check_in_range(
      impact_velocity, 0., 1e9, section + "Impact velocity", "m/s");
    // cells across follow from the aspect ratio, at least one: a bar far
    // thinner than its cells would have degenerate cells
    const double cell_aspect = length / cells_along_length /
                               std::min(height, length / cells_along_length);
    AssertThrow(cell_aspect <= 1e3,
                ExcMessage(
                  section + "Height = " + Utilities::to_string(height) +
                  " m is less than 1/1000 of a cell's length (" + section +
                  "Length / " + section + "Cells along length = " +
                  Utilities::to_string(length / cells_along_length) +
                  " m): the cells would be degenerate. Use more cells "
                  "along the length or a thicker bar."));
    AssertThrow(!(fixed_far_end && initial_strain != 0.),
                ExcMessage(
                  section + "Initial strain = " +
                  Utilities::to_string(initial_strain) + " and " + section +
                  "Fixed far end = true cannot be combined: the clamp would "
                  "cut off the strained displacement at x = L (a jump in the "
                  "last cell). Use one of them."));
    AssertThrow(
      std::isfinite(axial_body_force) && std::isfinite(end_traction),
      ExcMessage(
        "Scene/Bar impact/Body force and Scene/Bar impact/End traction must be "
        "finite numbers."));
    AssertThrow(std::isfinite(initial_gap),
                ExcMessage(
                  "Scene/Bar impact/Initial gap must be a finite number (m; "
                  "negative: the bar starts inside the wall)."));
    AssertThrow(
      std::isfinite(initial_strain) && initial_strain > -1.,
      ExcMessage(
        "Scene/Bar impact/Initial strain must be a finite number > -1."));
    AssertThrow(std::isfinite(angle),
                ExcMessage(
                  "Scene/Bar impact/Rotation angle must be a finite number."));
  }



  template <int dim>
  Tensor<1, dim>
  BarImpact<dim>::rotate(const Tensor<1, dim> &v) const
  {
    Tensor<1, dim> w = v;
    w[0]             = std::cos(angle) * v[0] - std::sin(angle) * v[1];
    w[1]             = std::sin(angle) * v[0] + std::cos(angle) * v[1];
    return w;
  }



  template <int dim>
  Tensor<1, dim>
  BarImpact<dim>::rotate_back(const Tensor<1, dim> &v) const
  {
    Tensor<1, dim> w = v;
    w[0]             = std::cos(angle) * v[0] + std::sin(angle) * v[1];
    w[1]             = -std::sin(angle) * v[0] + std::cos(angle) * v[1];
    return w;
  }



  template <int dim>
  double
  BarImpact<dim>::n_coarse_cells() const
  {
    const double n_across =
      std::max(1., std::round(double(cells_along_length) * height / length));
    return cells_along_length * std::pow(n_across, dim - 1);
  }



  template <int dim>
  void
  BarImpact<dim>::create_coarse_mesh(Triangulation<dim, dim> &tria) const
  {
    const unsigned int n_across =
      std::max<unsigned int>(1,
                             std::lround(cells_along_length * height / length));
    std::vector<unsigned int> repetitions(dim, n_across);
    repetitions[0] = cells_along_length;
    Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = (d == 0 ? length : height);
    // colorize: x = 0 gets id 0 (the contact boundary), x = L id 1, ...
    GridGenerator::subdivided_hyper_rectangle(
      tria, repetitions, Point<dim>(), upper, true);
    // colorize also numbers the cells; the bar is body 0
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    if (angle != 0.)
      GridTools::transform(
        [this](const Point<dim> &p) { return Point<dim>(rotate(p)); }, tria);
  }



  template <int dim>
  std::vector<DirichletBoundary>
  BarImpact<dim>::dirichlet_boundaries() const
  {
    if (fixed_far_end)
      return {DirichletBoundary{1}};
    return {};
  }



  template <int dim>
  std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
  BarImpact<dim>::neumann_tractions() const
  {
    if (end_traction == 0.)
      return {};
    Tensor<1, dim> e_x;
    e_x[0] = 1.;
    return {{types::boundary_id(0), end_traction * rotate(e_x)}};
  }



  template <int dim>
  Tensor<1, dim>
  BarImpact<dim>::body_force(const unsigned int) const
  {
    Tensor<1, dim> e_x;
    e_x[0] = 1.;
    return axial_body_force * rotate(e_x);
  }



  template <int dim>
  Tensor<1, dim>
  BarImpact<dim>::initial_displacement(const Point<dim> &p,
                                       const unsigned int) const
  {
    Tensor<1, dim> e_x;
    e_x[0] = 1.;
    return initial_strain * rotate_back(p)[0] * rotate(e_x);
  }



  template <int dim>
  Tensor<1, dim>
  BarImpact<dim>::initial_velocity(const Point<dim> &, const unsigned int) const
  {
    Tensor<1, dim> e_x;
    e_x[0] = 1.;
    return -impact_velocity * rotate(e_x);
  }



  template <int dim>
  std::vector<RigidObstacle<dim>>
  BarImpact<dim>::obstacles() const
  {
    Tensor<1, dim> e_x;
    e_x[0] = 1.;
    RigidObstacle<dim> wall;
    wall.point        = Point<dim>(-initial_gap * rotate(e_x));
    wall.normal       = rotate(e_x);
    wall.boundary_ids = contact_boundary_ids();
    return {wall};
  }



  template <int dim>
  bool
  BarImpact<dim>::has_exact_solution() const
  {
    // the 1D solution is exact for nu = 0 and an elastic bar
    const Material &mat = this->material(0);
    return mat.poissons_ratio == 0. && !mat.is_viscous() &&
           initial_strain == 0. && impact_velocity > 0. && initial_gap >= 0. &&
           !fixed_far_end && axial_body_force == 0. && end_traction == 0.;
  }



  template <int dim>
  ExactValues<dim>
  BarImpact<dim>::exact_solution(const Point<dim> &p, const double t) const
  {
    const BarSolution1D bar =
      exact_bar_impact_1d(rotate_back(p)[0],
                          t,
                          length,
                          this->material(0).bar_wave_speed(),
                          impact_velocity,
                          initial_gap);
    const double u = bar.displacement, v = bar.velocity, dudx = bar.strain;

    Tensor<1, dim> e_x;
    e_x[0]                 = 1.;
    const Tensor<1, dim> e = rotate(e_x);
    ExactValues<dim>     values;
    values.displacement          = u * e;
    values.velocity              = v * e;
    values.displacement_gradient = dudx * outer_product(e, e);
    return values;
  }


  DYNCONTACT_REGISTER_SCENE(BarImpact,
                            "bar impact",
                            "a bar against a rigid wall, with an exact "
                            "solution")
} // namespace dyncontact
