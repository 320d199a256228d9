#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/base/memory_check.h>
#include <dyncontact/scenes/hertz.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
  namespace
  {
    // boundary ids of the Hertz scenes
    constexpr types::boundary_id curved_id = 1, top_id = 2, symmetry_x_id = 3,
                                 block_top_id = 4, block_bottom_id = 5,
                                 free_id = 6, symmetry_z_id = 7,
                                 // with the upper block
      curved_upper_id = 8, upper_bottom_id = 9, upper_top_id = 10;
  } // namespace



  template <int dim>
  void
  HertzScene<dim>::declare_parameters(ParameterHandler  &prm,
                                      const std::string &subsection)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection(subsection);
    prm.declare_entry("Radius",
                      "1",
                      Patterns::Double(1e-9, 1e9),
                      "Radius R of the cylinder or "
                      "ball, in m (> 0).");
    prm.declare_entry("Block width",
                      "4",
                      Patterns::Double(0.),
                      "Width of the meshed (half) "
                      "block from the symmetry plane, in m (> Radius).");
    prm.declare_entry("Block depth",
                      "4",
                      Patterns::Double(0.),
                      "Depth of the block below its "
                      "top y = 0, in m (> 0).");
    prm.declare_entry("Load",
                      "0.005",
                      Patterns::Double(0., 1e30),
                      "Total load pressing the "
                      "cylinder (per unit thickness, N/m, in 2D) or the ball "
                      "(N, in 3D) into the block, applied as a uniform "
                      "traction on its flat top (>= 0).");
    prm.declare_entry("Drop velocity",
                      "0",
                      Patterns::Double(0., 1e9),
                      "Initial downward speed of the "
                      "cylinder or ball, in m/s (>= 0).");
    prm.declare_entry("Contact zone refinements",
                      "3",
                      Patterns::Integer(0, 10),
                      "How often the cells near the first contact point are "
                      "refined after the global refinements: within the "
                      "initial gap plus 2.5 times Hertz's static contact "
                      "size under the Load, or 1.5 times the largest "
                      "contact size of Hertz's impact at the Drop velocity, "
                      "if larger.");
    prm.declare_entry(
      "Extra refinements of the curved body",
      "0",
      Patterns::Integer(0, 5),
      "How often the cells of the cylinder or ball (body 1) in the contact "
      "zone are refined after the 'Contact zone refinements' of both "
      "bodies. With one or more, the curved body is the finer side and "
      "hence the slave ('Contact/Slave side = auto') against the flat "
      "block: every row's normal is then vertical, and the nodal pressures "
      "oscillate less than against a polygonal curved master surface "
      "(doc/results.md, Hertz).");
    prm.declare_entry(
      "Block mesh",
      "uniform",
      Patterns::Selection("uniform|matched"),
      "Coarse cells of the block along its top. 'uniform': cells of about "
      "R/2. 'matched': the first cell from the plane(s) of symmetry is "
      "pi R/4 wide, the arc of the curved body's coarse surface cell at its "
      "lowest point, the others about R/2; refined as often as the curved "
      "body (no 'Extra refinements of the curved body'), the block's top "
      "nodes then lie under the curved body's surface nodes, to within "
      "r^3/(6 R^2) at a distance r from the axis, so that the collocation "
      "of the slave nodes on the master surface is nearly node to node and "
      "the nodal pressures do not oscillate (doc/results.md, Hertz). The "
      "curved body is then the slave unless 'Contact/Slave side' says "
      "otherwise.");
    prm.declare_entry("Initial gap",
                      "0.1",
                      Patterns::Double(0., 1e9),
                      "Distance between the lowest point of the cylinder or "
                      "ball and the block's top, in m (>= 0); with the upper "
                      "block also between its top point and the upper "
                      "block.");
    prm.declare_entry(
      "Upper block",
      "false",
      Patterns::Bool(),
      "A third body: a block like the lower one (material 'Material of "
      "body 2') above a whole cylinder or ball, Initial gap above its top "
      "point. The Load then acts on the upper block's top, and the Drop "
      "velocity moves the upper block with the cylinder or ball. Two "
      "contact pairs (1: the lower block, 2: the upper block), both of "
      "Hertz's solution in the static problem.");
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  void
  HertzScene<dim>::parse_parameters(ParameterHandler &prm)
  {
    AssertThrow(dim == scene_dimension,
                ExcMessage(scene_dimension == 2 ?
                             "Scene 'hertz' is two-dimensional (set "
                             "Dimension = 2); its 3D counterpart is 'ball "
                             "on block'." :
                             "Scene 'ball on block' is three-dimensional "
                             "(set Dimension = 3); its 2D counterpart is "
                             "'hertz'."));
    prm.enter_subsection("Scene");
    prm.enter_subsection(subsection);
    radius              = prm.get_double("Radius");
    block_width         = prm.get_double("Block width");
    block_depth         = prm.get_double("Block depth");
    load                = prm.get_double("Load");
    drop_velocity       = prm.get_double("Drop velocity");
    initial_gap         = prm.get_double("Initial gap");
    contact_refinements = prm.get_integer("Contact zone refinements");
    extra_refinements = prm.get_integer("Extra refinements of the curved body");
    matched_block_mesh = (prm.get("Block mesh") == "matched");
    upper_block        = prm.get_bool("Upper block");
    prm.leave_subsection();
    prm.leave_subsection();
    const std::string where = "Scene/" + subsection + "/";

    check_in_range(radius, 1e-9, 1e9, where + "Radius", "m");
    check_in_range(block_width, 0., 1e3 * radius, where + "Block width", "m");
    check_in_range(block_depth, 0., 1e3 * radius, where + "Block depth", "m");
    AssertThrow(std::isfinite(block_width) && block_width > radius,
                ExcMessage(where + "Block width must be a finite number > " +
                           where + "Radius (m)."));
    AssertThrow(std::isfinite(block_depth) && block_depth > 0.,
                ExcMessage(where +
                           "Block depth must be a finite number > 0 (m)."));
    AssertThrow(std::isfinite(load) && load >= 0.,
                ExcMessage(where + "Load must be a finite number >= 0."));
    check_in_range(load, 0., 1e30, where + "Load", dim == 2 ? "N/m" : "N");
    AssertThrow(std::isfinite(drop_velocity) && drop_velocity >= 0.,
                ExcMessage(
                  where + "Drop velocity must be a finite number >= 0 (m/s)."));
    AssertThrow(std::isfinite(initial_gap) && initial_gap >= 0.,
                ExcMessage(where +
                           "Initial gap must be a finite number >= 0 (m)."));
  }



  template <int dim>
  double
  HertzScene<dim>::effective_modulus() const
  {
    double inverse = 0.;
    for (unsigned int b = 0; b < 2; ++b)
      {
        const Material &m = this->material(b);
        inverse +=
          (1. - m.poissons_ratio * m.poissons_ratio) / m.youngs_modulus;
      }
    return 1. / inverse;
  }



  template <int dim>
  double
  HertzScene<dim>::hertz_contact_size() const
  {
    const double E = effective_modulus();
    if (dim == 2)
      return std::sqrt(4. * load * radius / (M_PI * E));
    return std::cbrt(3. * load * radius / (4. * E));
  }



  template <int dim>
  double
  HertzScene<dim>::impact_contact_size() const
  {
    const double E    = effective_modulus();
    const double rho  = this->material(0).density;
    double       mass = (dim == 2) ? 0.5 * M_PI * radius * radius * rho :
                                     2. / 3. * M_PI * std::pow(radius, 3) * rho;
    if (upper_block)
      // the whole body and the upper block drop
      mass = 2. * mass + this->material(1).density * block_depth *
                           std::pow(2. * block_width, dim - 1);
    const double energy = 0.5 * mass * drop_velocity * drop_velocity;
    // stored energy less the load's work over the indentation, for the
    // contact size s: increasing where it matters, negative at s -> 0
    const auto balance = [&](const double s) {
      if (dim == 3)
        {
          const double alpha = s * s / radius;
          return 8. / 15. * E * std::sqrt(radius) * std::pow(alpha, 2.5) -
                 load * alpha - energy;
        }
      const double force    = M_PI * E * s * s / (4. * radius);
      const double log_term = 2. * std::log(4. * radius / s);
      const double alpha    = force / (M_PI * E) * (log_term - 1.);
      return force * force / (2. * M_PI * E) * (log_term - 1.5) - load * alpha -
             energy;
    };
    if (energy <= 0.)
      return 0.;
    if (balance(radius) <= 0.)
      return radius;
    double low = 0., high = radius;
    for (unsigned int i = 0; i < 60; ++i)
      {
        const double middle                 = 0.5 * (low + high);
        (balance(middle) > 0. ? high : low) = middle;
      }
    return high;
  }



  template <int dim>
  std::optional<double>
  HertzScene<dim>::exact_contact_pressure(const Point<dim> &x) const
  {
    const double size = hertz_contact_size();
    const double p0   = (dim == 2) ? 2. * load / (M_PI * size) :
                                     3. * load / (2. * M_PI * size * size);
    double       r2   = x[0] * x[0];
    if (dim == 3)
      r2 += x[dim - 1] * x[dim - 1];
    const double s = 1. - r2 / (size * size);
    return s > 0. ? p0 * std::sqrt(s) : 0.;
  }



  template <int dim>
  std::vector<double>
  HertzScene<dim>::block_column_widths() const
  {
    // (the block width exceeds the radius, hence pi R/4 as well)
    const double first = matched_block_mesh ? M_PI / 4. * radius : 0.;
    const double rest  = block_width - first;
    const auto   n_rest =
      std::max<unsigned int>(1, std::lround(2. * rest / radius));
    std::vector<double> widths(first > 0. ? 1 : 0, first);
    widths.resize(widths.size() + n_rest, rest / n_rest);
    return widths;
  }



  template <int dim>
  double
  HertzScene<dim>::n_coarse_cells() const
  {
    const double columns = block_column_widths().size();
    double       block =
      std::max(1., std::round(2. * block_depth / radius)) * columns;
    if (dim == 3)
      block *= columns;
    return (upper_block ? 2. : 1.) * ((dim == 2 ? 3. : 4.) + block);
  }



  template <int dim>
  void
  HertzScene<dim>::create_coarse_mesh(Triangulation<dim, dim> &tria) const
  {
    // the cylinder/ball: a quarter disc (1/8 ball) in x, y >= 0 turned by
    // -90 degrees about z into x >= 0, y <= 0, then lifted so that its
    // lowest point is at (0, g0)
    const double            centre_height = radius + initial_gap;
    Triangulation<dim, dim> body;
    GridGenerator::quarter_hyper_ball(body, Point<dim>(), radius);
    Triangulation<dim, dim> upper_half;
    if (upper_block)
      {
        // the upper half: the same quarter disc (1/8 ball) lifted, merged
        // into one body with the lower half
        upper_half.copy_triangulation(body);
        Tensor<1, dim> lift;
        lift[1] = centre_height;
        GridTools::shift(lift, upper_half);
      }
    GridTools::transform(
      [&](const Point<dim> &p) {
        Point<dim> q = p;
        q[0]         = p[1];
        q[1]         = centre_height - p[0];
        return q;
      },
      body);
    if (upper_block)
      {
        Triangulation<dim, dim> lower_half;
        lower_half.copy_triangulation(body);
        body.clear();
        GridGenerator::merge_triangulations(
          lower_half, upper_half, body, 1e-12 * radius, true);
      }

    // the block [0, W] x [-D, 0] (x [0, W]), cells of about R/2 (matched:
    // the first column pi R/4 wide)
    Triangulation<dim, dim>          block;
    std::vector<std::vector<double>> step_sizes(dim);
    std::vector<unsigned int>        repetitions(dim);
    Point<dim>                       lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        step_sizes[d] = block_column_widths();
        if (d == 1)
          {
            const auto n =
              std::max<unsigned int>(1, std::lround(2. * block_depth / radius));
            step_sizes[d].assign(n, block_depth / n);
          }
        repetitions[d] = step_sizes[d].size();
        lower[d]       = (d == 1) ? -block_depth : 0.;
        upper[d]       = (d == 1) ? 0. : block_width;
      }
    if (matched_block_mesh)
      GridGenerator::subdivided_hyper_rectangle(block,
                                                step_sizes,
                                                lower,
                                                upper);
    else
      GridGenerator::subdivided_hyper_rectangle(block,
                                                repetitions,
                                                lower,
                                                upper);

    // the upper block: the lower one lifted to y = 2 R + 2 g0
    const double            upper_bottom = 2. * centre_height;
    Triangulation<dim, dim> upper_block_mesh;
    if (upper_block)
      {
        upper_block_mesh.copy_triangulation(block);
        Tensor<1, dim> lift;
        lift[1] = upper_bottom + block_depth;
        GridTools::shift(lift, upper_block_mesh);
        merge_bodies<dim>({&body, &block, &upper_block_mesh}, tria);
      }
    else
      merge_bodies<dim>({&body, &block}, tria);

    const double tolerance = 1e-8 * radius;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<dim>   c = cell->face(f)->center();
            types::boundary_id id;
            if (std::abs(c[0]) < tolerance)
              id = symmetry_x_id;
            else if (dim == 3 && std::abs(c[dim - 1]) < tolerance)
              id = symmetry_z_id;
            else if (cell->material_id() == 0)
              id = upper_block ?
                     (c[1] > centre_height ? curved_upper_id : curved_id) :
                     (std::abs(c[1] - centre_height) < tolerance ? top_id :
                                                                   curved_id);
            else if (cell->material_id() == 2)
              id = std::abs(c[1] - upper_bottom) < tolerance ?
                     upper_bottom_id :
                     (std::abs(c[1] - upper_bottom - block_depth) < tolerance ?
                        upper_top_id :
                        free_id);
            else if (std::abs(c[1]) < tolerance)
              id = block_top_id;
            else if (std::abs(c[1] + block_depth) < tolerance)
              id = block_bottom_id;
            else
              id = free_id;
            cell->face(f)->set_boundary_id(id);
            if (id == curved_id || id == curved_upper_id)
              cell->face(f)->set_manifold_id(0);
          }
    Point<dim> centre;
    centre[1] = centre_height;
    tria.set_manifold(0, SphericalManifold<dim>(centre));
  }



  template <int dim>
  void
  HertzScene<dim>::refine_initial_mesh(Triangulation<dim, dim> &tria) const
  {
    // refine towards the first contact point (the origin): within 2.5
    // times Hertz's static contact size under the load, and within 1.5
    // times the largest contact size of a drop
    const double zone =
      std::max(2.5 * hertz_contact_size(), 1.5 * impact_contact_size()) +
      initial_gap;
    // (and towards the upper one, with the upper block)
    Point<dim> upper_point;
    upper_point[1]      = 2. * radius + 2. * initial_gap;
    const auto distance = [&](const Point<dim> &x) {
      return upper_block ? std::min(x.norm(), x.distance(upper_point)) :
                           x.norm();
    };
    // (both bodies, then the curved body alone its extra times)
    for (unsigned int k = 0; k < contact_refinements + extra_refinements; ++k)
      {
        double flagged = 0.;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() &&
              (k < contact_refinements || cell->material_id() == 0) &&
              distance(cell->center()) < zone + 0.5 * cell->diameter())
            {
              cell->set_refine_flag();
              ++flagged;
            }
        const MPI_Comm comm = tria.get_communicator();
        check_mesh_fits_in_memory(tria.n_global_active_cells() +
                                    ((1 << dim) - 1) *
                                      Utilities::MPI::sum(flagged, comm),
                                  dim,
                                  this->polynomial_degree,
                                  this->stored_step_matrix,
                                  n_coarse_cells(),
                                  "Scene/" + subsection +
                                    "/Contact zone refinements (now " +
                                    std::to_string(contact_refinements) +
                                    "), Extra refinements of the curved "
                                    "body (now " +
                                    std::to_string(extra_refinements) +
                                    ") or Mesh/Initial global refinements",
                                  comm);
        tria.execute_coarsening_and_refinement();
      }
  }



  template <int dim>
  std::vector<ContactPair>
  HertzScene<dim>::contact_pairs() const
  {
    ContactPair pair;
    pair.first_side    = {curved_id};
    pair.second_side   = {block_top_id};
    pair.search_radius = initial_gap + 0.5 * radius;
    // on the matched block mesh the curved body is the slave (the default
    // choice, the finer side by mean face size, may take the block)
    if (matched_block_mesh)
      pair.slave_side = 0;
    if (!upper_block)
      return {pair};
    ContactPair upper_pair = pair;
    upper_pair.first_side  = {curved_upper_id};
    upper_pair.second_side = {upper_bottom_id};
    return {pair, upper_pair};
  }



  template <int dim>
  std::vector<DirichletBoundary>
  HertzScene<dim>::dirichlet_boundaries() const
  {
    std::vector<DirichletBoundary> boundaries;
    boundaries.push_back({symmetry_x_id, {{true, false, false}}});
    if (dim == 3)
      boundaries.push_back({symmetry_z_id, {{false, false, true}}});
    boundaries.push_back({block_bottom_id, {{true, true, true}}});
    return boundaries;
  }



  template <int dim>
  std::vector<types::boundary_id>
  HertzScene<dim>::symmetry_boundary_ids() const
  {
    if (dim == 3)
      return {symmetry_x_id, symmetry_z_id};
    return {symmetry_x_id};
  }



  template <int dim>
  std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
  HertzScene<dim>::neumann_forces() const
  {
    // the share of the load on the meshed part: half (2D) or a quarter (3D)
    Tensor<1, dim> force;
    force[1] = -load / (dim == 2 ? 2. : 4.);
    return {{upper_block ? upper_top_id : top_id, force}};
  }



  template <int dim>
  Tensor<1, dim>
  HertzScene<dim>::initial_velocity(const Point<dim>  &x,
                                    const unsigned int body) const
  {
    Tensor<1, dim> v;
    (void)x;
    if (body == 0 || body == 2)
      v[1] = -drop_velocity;
    return v;
  }

  template class HertzScene<2>;
  template class HertzScene<3>;

  DYNCONTACT_REGISTER_SCENE(Hertz,
                            "hertz",
                            "2D: a half-cylinder pressed into or dropping "
                            "onto a block")
  DYNCONTACT_REGISTER_SCENE(BallOnBlock,
                            "ball on block",
                            "3D: a ball pressed into or dropping onto a "
                            "block")
} // namespace dyncontact
