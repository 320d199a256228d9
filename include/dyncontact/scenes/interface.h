#ifndef dyncontact_scenes_interface_h
#define dyncontact_scenes_interface_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <dyncontact/base/plugins.h>
#include <dyncontact/scenes/material.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
  template <int dim, int spacedim>
  class Triangulation;
} // namespace dealii

namespace dyncontact
{
  using namespace dealii;

  /**
   * A rigid obstacle: the half-space {x : (x - point) . normal <= 0}, with
   * @p normal the unit normal pointing out of the obstacle into free space;
   * or a ball (in 2D a disc) of centre @p point and radius @p radius; or
   * (3D) a solid cylinder of radius @p radius about the axis through
   * @p point along the unit vector @p normal. For a slave node x_p it gives
   * the outward normal n and the gap g of the obstacle's surface at its
   * point closest to x_p, nu_p = -n and g_p (the paper's eqs. 2-3, the
   * constraint linearised at the reference position).
   */
  template <int dim>
  struct RigidObstacle
  {
    enum class Shape
    {
      half_space,
      ball,
      cylinder
    };
    Shape          shape = Shape::half_space;
    Point<dim>     point;
    Tensor<1, dim> normal;
    double         radius = 0.;
    /// The boundary ids that meet it.
    std::vector<types::boundary_id> boundary_ids;
    /// A prescribed translation d(t) of the obstacle (m, dim components of
    /// a function of t alone); nullptr: it stays where it is. The shape
    /// above is its position at d = 0.
    std::shared_ptr<Function<dim>> motion;

    /// d(t) (zero without a motion); a value that is not finite or beyond
    /// 1e15 m is refused naming the obstacle @p k (from 1).
    Tensor<1, dim>
    displacement(const double t, const unsigned int k) const
    {
      Tensor<1, dim> d;
      if (motion == nullptr)
        return d;
      motion->set_time(t);
      for (unsigned int c = 0; c < dim; ++c)
        {
          d[c] = motion->value(Point<dim>(), c);
          if (!(std::isfinite(d[c]) && std::abs(d[c]) <= 1e15))
            {
              std::ostringstream text;
              text << "The motion of obstacle " << k
                   << " (Scene/Gmsh/Obstacles, 'moving') is " << d[c]
                   << " m in component " << c + 1 << " at t = " << t
                   << " s: it must be finite and at most 1e15 m (N-CS++ "
                      "takes it at t_{n+1} + tau, one step beyond End time "
                      "in its last step).";
              AssertThrow(false, ExcMessage(text.str()));
            }
        }
      return d;
    }

    /// The gap of @p x (negative inside) and the outward unit normal of
    /// the surface at its point closest to @p x (zero on a ball's centre or
    /// a cylinder's axis, where it has none).
    std::pair<double, Tensor<1, dim>>
    gap_and_normal(const Point<dim> &x) const
    {
      if (shape == Shape::half_space)
        return {(x - point) * normal, normal};
      Tensor<1, dim> d = x - point;
      if (shape == Shape::cylinder)
        d -= (d * normal) * normal;
      const double r = d.norm();
      return {r - radius, r > 0. ? Tensor<1, dim>(d / r) : Tensor<1, dim>()};
    }
  };

  /// Homogeneous Dirichlet data on one boundary id, for some components.
  struct DirichletBoundary
  {
    types::boundary_id id;
    /// Which displacement components are fixed (only the first dim count).
    std::array<bool, 3> components{{true, true, true}};
  };

  /**
   * A two-body contact pair: the boundary ids of the possible contact
   * boundaries of the two sides, which side is the slave, and how far from a
   * slave node the contact search looks for the master surface. The scene
   * gives its defaults; subsection "Contact" may override them.
   */
  struct ContactPair
  {
    std::vector<types::boundary_id> first_side;
    std::vector<types::boundary_id> second_side;
    /// -1: automatic (the finer side), 0: the first side, 1: the second side.
    int slave_side = -1;
    /// In m; slave nodes farther than this from the master get no row; 0:
    /// the scene has no default.
    double search_radius = 0.;
    /// Whether the input gave this pair its own search radius (e.g. in
    /// Scene/Gmsh/Contact pairs): then Contact/Search radius, the radius of
    /// every other pair, does not override it.
    bool own_search_radius = false;
    /// Whether the input named this pair's slave (e.g. 'slave : master' in
    /// Scene/Gmsh/Contact pairs): Contact/Slave side may not override it.
    bool own_slave_side = false;
  };

  /**
   * Loads given as functions of x (and t, Function::set_time()): a body
   * force density per body (N/m^3, dim components; nullptr: none), a
   * traction (Pa, dim components) or a normal pressure (Pa, one component,
   * positive pushing into the body: the traction -p n) per boundary id.
   * They add to the constant loads (Scene::body_force(),
   * neumann_tractions()). Those in @p of_time (which depend on t) the
   * system evaluates at every step's end (doc/algorithms.md, "Loads that
   * change in time"), the others once per mesh.
   */
  template <int dim>
  struct FunctionLoads
  {
    std::vector<Function<dim> *>                                body_forces;
    std::vector<std::pair<types::boundary_id, Function<dim> *>> tractions;
    std::vector<std::pair<types::boundary_id, Function<dim> *>> pressures;
    /// the functions above that depend on t
    std::set<const Function<dim> *> of_time;
    /// whether any of them depends on t
    bool time_dependent = false;

    bool
    empty() const
    {
      return tractions.empty() && pressures.empty() &&
             std::none_of(body_forces.begin(),
                          body_forces.end(),
                          [](const Function<dim> *f) { return f != nullptr; });
    }
  };

  template <int dim>
  class Scene;

  template <int dim>
  std::unique_ptr<Scene<dim>>
  create_scene(ParameterHandler  &prm,
               const std::string &input_directory,
               const unsigned int polynomial_degree,
               const bool         stored_step_matrix);

  /// The exact solution at one point and time, where a scene knows it.
  template <int dim>
  struct ExactValues
  {
    Tensor<1, dim> displacement;
    Tensor<1, dim> velocity;
    Tensor<2, dim> displacement_gradient;
  };

  /**
   * A scene decides what exists: the mesh with its boundary ids, the
   * materials, loads, initial data, the obstacle and, if known, the exact
   * solution. Nothing is assembled or searched that the scene does not ask
   * for.
   *
   * Scenes are plugins: a new scene is one file with its class and the line
   * DYNCONTACT_REGISTER_SCENE(Class, "name", "description"). Its parameters
   * live in its own subsection "Scene/<Name>" (declared by its static
   * declare_parameters(), read by parse_parameters()), so no scene reads
   * another's entries.
   */
  template <int dim>
  class Scene
  {
  public:
    virtual ~Scene() = default;

    /// Declares the scene's subsection; nothing by default.
    static void
    declare_parameters(ParameterHandler &)
    {}

    /// Reads and checks the scene's subsection "Scene/<Name>".
    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /// The name under which the scene is registered.
    const std::string &
    name() const
    {
      return scene_name;
    }

    /// The coarse mesh with boundary ids (before global refinement). Each
    /// cell's material id is the index of its body.
    virtual void
    create_coarse_mesh(Triangulation<dim, dim> &triangulation) const = 0;

    /// Local refinement after the global refinements (e.g. towards the
    /// contact zone); by default none.
    virtual void
    refine_initial_mesh(Triangulation<dim, dim> &) const
    {}

    /// How many coarse cells create_coarse_mesh() will make (before any
    /// refinement), known from the parameters before the mesh is built, so
    /// that a mesh too large for the machine is refused before it is
    /// allocated; 0 if unknown.
    virtual double
    n_coarse_cells() const
    {
      return 0.;
    }

    /// A checksum of the input files the scene reads (e.g. a mesh file),
    /// kept in checkpoints: a resumed run refuses files changed since.
    virtual std::string
    input_checksum() const
    {
      return "";
    }

    /// Number of bodies (cells have material id 0 .. n_bodies()-1).
    virtual unsigned int
    n_bodies() const
    {
      return 1;
    }

    /// Entries (or subsections) that the input may set but that this
    /// scene, as configured, does not read: (full name, why), for the
    /// warnings before the run. Here: Material of body 2 where no body is
    /// of it (material_subsections()).
    virtual std::vector<std::pair<std::string, std::string>>
    unread_entries() const;

    /// The material subsection of each body: by default "Material" for
    /// body 1 and "Material of body 2" for every other. (Lists of one value
    /// per body in subsection Material override it.)
    virtual std::vector<std::string>
    material_subsections() const;

    /// Whether all bodies are of one material (a scene's exact solution
    /// may need it).
    bool
    one_material() const;

    const Material &
    material(const unsigned int body) const
    {
      return materials[body];
    }

    /// Boundary ids that touch a rigid obstacle (the union of those of
    /// obstacles()).
    virtual std::vector<types::boundary_id>
    contact_boundary_ids() const
    {
      return {};
    }

    /// Two-body contact pairs; none by default.
    virtual std::vector<ContactPair>
    contact_pairs() const
    {
      return {};
    }

    /// Boundaries that are planes of symmetry of the model (rollers, as in
    /// a half or quarter model): the bodies continue across them, so an edge
    /// of a contact surface on such a plane is no rim of the surface.
    virtual std::vector<types::boundary_id>
    symmetry_boundary_ids() const
    {
      return {};
    }

    /// Boundaries with homogeneous Dirichlet data.
    virtual std::vector<DirichletBoundary>
    dirichlet_boundaries() const
    {
      return {};
    }

    /// Dirichlet boundaries (of dirichlet_boundaries()) whose displacement
    /// moves: per boundary id the prescribed displacement g(x, t) (m, dim
    /// components, of which those the boundary fixes are used; a function
    /// of t through Function::set_time()). A node shared with a boundary
    /// that holds zero stays at zero. None by default.
    virtual std::vector<std::pair<types::boundary_id, Function<dim> *>>
    prescribed_displacements() const
    {
      return {};
    }

    /// Constant Neumann tractions (Pa) per boundary id.
    virtual std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
    neumann_tractions() const
    {
      return {};
    }

    /// Constant Neumann loads given as total forces (N; in 2D per unit
    /// thickness) per boundary id, spread uniformly over the boundary as
    /// the mesh represents it (so that they sum to the force exactly, also
    /// where a curved boundary is approximated by a polygon).
    virtual std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
    neumann_forces() const
    {
      return {};
    }

    /// Constant body force density (N/m^3) in the given body.
    virtual Tensor<1, dim>
    body_force(const unsigned int /*body*/) const
    {
      return Tensor<1, dim>();
    }

    /// Loads given as functions (FunctionLoads); none by default.
    virtual FunctionLoads<dim>
    function_loads() const
    {
      return {};
    }

    /// Initial displacement at x in the given body.
    virtual Tensor<1, dim>
    initial_displacement(const Point<dim> &, const unsigned int /*body*/) const
    {
      return Tensor<1, dim>();
    }

    /// Initial velocity at x in the given body.
    virtual Tensor<1, dim>
    initial_velocity(const Point<dim> &x, const unsigned int body) const = 0;

    /// The rigid obstacles, each a contact pair of its own (numbered after
    /// the two-body pairs), with the boundary ids that meet it; none by
    /// default.
    virtual std::vector<RigidObstacle<dim>>
    obstacles() const
    {
      return {};
    }

    virtual bool
    has_exact_solution() const
    {
      return false;
    }

    virtual ExactValues<dim>
    exact_solution(const Point<dim> &, const double) const
    {
      return {};
    }

    /// The exact contact pressure (Pa) of the static problem at the
    /// reference position @p x of a slave node, where the scene knows it
    /// (Hertz), else nothing.
    virtual std::optional<double>
    exact_contact_pressure(const Point<dim> & /*x*/) const
    {
      return {};
    }

    /// Boundary ids of every possible contact boundary (obstacle and pairs).
    std::vector<types::boundary_id>
    all_contact_boundary_ids() const;

    /// Whether the scene has any contact (an obstacle or a pair).
    bool
    has_contact() const;

    /// Whether any body is viscous (else no viscous matrix is assembled).
    bool
    is_viscous() const;

    /// The scene's subsection, "Scene/<Name capitalised>".
    std::string
    subsection() const;

    /// Whether the memory estimates count a stored step matrix.
    bool
    stores_step_matrix() const
    {
      return stored_step_matrix;
    }

  protected:
    /// The folder of the prm file: relative file names refer to it.
    std::string input_directory;

    /// The degree of the finite elements (for memory estimates).
    unsigned int polynomial_degree = 1;
    /// Whether the step matrix is stored ('Contact solver/Step matrix =
    /// assembled'; for memory estimates).
    bool stored_step_matrix = true;

  private:
    std::string           scene_name;
    std::vector<Material> materials;
    /// Whether the materials came from lists in subsection Material.
    bool materials_per_body = false;

    friend std::unique_ptr<Scene<dim>>
    create_scene<dim>(ParameterHandler  &prm,
                      const std::string &input_directory,
                      const unsigned int polynomial_degree,
                      const bool         stored_step_matrix);
  };

  extern template class PluginRegistry<Scene>;

  /// Declares subsection "Scene" with "Name" and every scene's subsection.
  void
  declare_scene_parameters(ParameterHandler &prm);

  /// Creates the scene named in "Scene/Name", reads its parameters and the
  /// materials of its bodies; relative file names in the scene's parameters
  /// are relative to @p input_directory (the prm file's folder). The
  /// memory estimates of its mesh are handed what they need by the owners
  /// of the entries: the Polynomial degree and whether the step matrix is
  /// stored (Contact solver/Step matrix = assembled).
  template <int dim>
  std::unique_ptr<Scene<dim>>
  create_scene(ParameterHandler  &prm,
               const std::string &input_directory,
               const unsigned int polynomial_degree,
               const bool         stored_step_matrix);

  /**
   * Builds @p scene's mesh in @p triangulation: its coarse mesh, then
   * (unless @p coarse_only: a resumed run loads the refined mesh from its
   * checkpoint) @p global_refinements global refinements and the scene's
   * own. A mesh that would not fit into memory for FE_Q(@p degree)^dim is
   * refused before it is allocated; every cell must belong to a body.
   * Collective.
   */
  template <int dim>
  void
  build_mesh(const Scene<dim>        &scene,
             Triangulation<dim, dim> &triangulation,
             const unsigned int       global_refinements,
             const unsigned int       degree,
             const bool               coarse_only);

  /**
   * The boundary ids of each body's boundary faces, over all ranks.
   * Collective.
   */
  template <int dim>
  std::vector<std::set<types::boundary_id>>
  boundary_ids_of_bodies(const Triangulation<dim, dim> &triangulation,
                         const unsigned int             n_bodies);

  /// Whether @p ids_of_body (a body's entry of boundary_ids_of_bodies())
  /// holds any of @p ids.
  inline bool
  has_any_of(const std::set<types::boundary_id>    &ids_of_body,
             const std::vector<types::boundary_id> &ids)
  {
    return std::any_of(ids.begin(), ids.end(), [&](const auto id) {
      return ids_of_body.count(id) > 0;
    });
  }

  /**
   * Builds one coarse mesh from several coarse meshes (the bodies) without
   * merging any vertices, so that bodies touching at t = 0 stay separate.
   * Cell material ids become the index of the body; boundary and manifold
   * ids are kept.
   */
  template <int dim>
  void
  merge_bodies(const std::vector<const Triangulation<dim, dim> *> &bodies,
               Triangulation<dim, dim>                            &result);
} // namespace dyncontact

/// Registers a scene (see Scene).
#define DYNCONTACT_REGISTER_SCENE(classname, name, description) \
  DYNCONTACT_REGISTER_PLUGIN(dyncontact::Scene, classname, name, description)

#endif
