#ifndef dyncontact_scenes_gmsh_scene_h
#define dyncontact_scenes_gmsh_scene_h

#include <dyncontact/scenes/interface.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <int dim>
  class FunctionParser;
}

namespace dyncontact
{
  /**
   * Any mesh of one or more bodies from Gmsh (a .msh file, quadrilaterals
   * or hexahedra). Physical tags are mapped in the prm: cell tags to bodies,
   * boundary tags to clamped (Dirichlet), loaded (Neumann) and contact
   * boundaries. Bodies must not share vertices. Two bodies can be given by
   * 'Body 1 tags' and 'Body 2 tags' (one contact pair); any number by
   * 'Bodies', with 'Contact tags', 'Initial velocities' and a list of
   * 'Contact pairs' (slave : master, body numbers, a master can be a
   * rigid obstacle, a half-space, a ball or a cylinder; a pair can have its
   * own search radius).
   * The mesh is checked against the prm: every cell must belong to a body,
   * every tag named in the prm must exist in the mesh, otherwise the run
   * stops with a message.
   */
  template <int dim>
  class GmshScene : public Scene<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    double
    n_coarse_cells() const override
    {
      return n_cells;
    }

    std::string
    input_checksum() const override
    {
      return mesh_checksum;
    }

    void
    create_coarse_mesh(Triangulation<dim, dim> &triangulation) const override;

    unsigned int
    n_bodies() const override
    {
      return body_tags.size();
    }

    std::vector<ContactPair>
    contact_pairs() const override;

    /// The contact tags of the bodies paired with an obstacle.
    std::vector<types::boundary_id>
    contact_boundary_ids() const override;

    /// The half-space of Obstacle point and Obstacle normal, or those of
    /// Obstacles, each with the tags that meet it.
    std::vector<RigidObstacle<dim>>
    obstacles() const override;

    std::vector<DirichletBoundary>
    dirichlet_boundaries() const override;

    std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
    neumann_tractions() const override;

    Tensor<1, dim>
    body_force(const unsigned int body) const override;

    /// Body force, Pressures and the tractions of Neumann tractions that
    /// are functions.
    FunctionLoads<dim>
    function_loads() const override;

    /// Prescribed displacements (of Dirichlet tags).
    std::vector<std::pair<types::boundary_id, Function<dim> *>>
    prescribed_displacements() const override;

    /// Initial displacement function at @p x in @p body (zero without).
    Tensor<1, dim>
    initial_displacement(const Point<dim>  &x,
                         const unsigned int body) const override;

    /// The Initial velocity function at @p x in @p body, or the body's
    /// constant initial velocity.
    Tensor<1, dim>
    initial_velocity(const Point<dim>  &x,
                     const unsigned int body) const override;

    std::vector<std::pair<std::string, std::string>>
    unread_entries() const override;

  private:
    /// @name The parts of parse_parameters() (within subsection Scene/Gmsh)
    /// @{

    /// Body 1 tags, Body 2 tags and their entries: one or two bodies, one
    /// pair.
    void
    parse_two_bodies(ParameterHandler &prm);

    /// @p bodies (Bodies) and the lists of one item per body: any number of
    /// bodies.
    void
    parse_body_list(ParameterHandler &prm, const std::string &bodies);

    /// Contact pairs (with Bodies).
    void
    parse_contact_pairs(ParameterHandler &prm);

    /// Obstacles, or Obstacle point and Obstacle normal (with pairs 'body :
    /// obstacle [k]'; in gmsh_obstacles.cc).
    void
    parse_obstacle(ParameterHandler &prm);

    /// Stops if a body has contact tags but no pair names it.
    void
    refuse_unpaired_contact_tags() const;

    /// Manifolds: boundary tags bound to a sphere or a cylinder.
    void
    parse_manifolds(ParameterHandler &prm);

    /// Initial displacement, Initial velocity and Function constants: one
    /// function parser per body (the constant 'body' is its number).
    void
    parse_initial_functions(ParameterHandler &prm);

    /// Neumann tractions, Pressures, Body force and Prescribed
    /// displacements (in gmsh_loads.cc).
    void
    parse_loads(ParameterHandler &prm);
    /// @}

    /// Binds the faces of each tag of Manifolds (and their edges) to its
    /// manifold, after checking that the tag is on the boundary (@p
    /// face_tags) and that all its vertices lie at one distance from the
    /// centre or the axis (or on the CAD surface).
    void
    attach_manifolds(Triangulation<dim, dim>      &tria,
                     const std::set<unsigned int> &face_tags) const;

    std::string mesh_file;
    double      n_cells = 0.;
    std::string mesh_checksum;
    /// Per body: its cell tags, its contact tags, its initial velocity.
    std::vector<std::set<unsigned int>>          body_tags;
    std::vector<std::vector<types::boundary_id>> contact_tags;
    std::vector<Tensor<1, dim>>                  velocity;
    /// The entry that gave each body's contact tags, for messages.
    std::vector<std::string> contact_entries;
    /// A pair of two bodies: slave and master, counted from 0, its own
    /// search radius (m; 0: Contact/Search radius), and the contact tags of
    /// each side (all of the body's, or those the pair names).
    struct BodyPair
    {
      unsigned int                    slave;
      unsigned int                    master;
      double                          search_radius;
      std::vector<types::boundary_id> slave_tags;
      std::vector<types::boundary_id> master_tags;
    };
    std::vector<BodyPair> pairs;
    /// Whether the pairs were listed in Contact pairs (they then name the
    /// slave).
    bool pairs_listed = false;
    /// Per rigid obstacle (numbered from 0): the bodies paired with it,
    /// their tags that meet it, and the obstacle; whether a pair names
    /// 'obstacle' without a number.
    std::vector<std::set<unsigned int>>       obstacle_slaves;
    std::vector<std::set<types::boundary_id>> obstacle_tags;
    std::vector<RigidObstacle<dim>>           rigid_obstacles;
    bool                                      unnumbered_obstacle = false;
    /// The Dirichlet tags, each with the displacement components it fixes.
    std::map<unsigned int, std::array<bool, 3>> dirichlet_components;
    std::set<unsigned int>                      neumann_tags;
    /// Tags with a traction of their own (Neumann tractions).
    std::map<unsigned int, Tensor<1, dim>> tag_tractions;
    /// A boundary tag bound to a sphere (in 2D a circle) of centre @p
    /// point, or to a cylinder (3D) of axis through @p point along @p axis.
    struct ManifoldBinding
    {
      unsigned int   tag;
      bool           cylinder = false;
      Point<dim>     point;
      Tensor<1, dim> axis;
      /// a CAD file (IGES or STEP; empty: a sphere or cylinder) and the
      /// factor from its lengths to m
      std::string cad_file;
      double      cad_scale = 1.;
    };
    std::vector<ManifoldBinding> manifolds;
    /// attach_manifolds() for a CAD binding: reads the file, checks that
    /// the tag's vertices lie on its surface (within 1e-3 of the tag's
    /// size) and binds the tag to OpenCASCADE's normal projection.
    void
    attach_cad_surface(Triangulation<dim, dim> &tria,
                       const ManifoldBinding   &binding) const;
    /// Per body (empty: none): the initial displacement and velocity as
    /// functions of x, y (, z).
    std::vector<std::shared_ptr<FunctionParser<dim>>> displacement_functions;
    std::vector<std::shared_ptr<FunctionParser<dim>>> velocity_functions;
    /// Per tag: a traction or pressure given by functions (of x, y, z and
    /// t), and per body (empty: none) the Body force.
    std::map<unsigned int, std::shared_ptr<FunctionParser<dim>>>
      traction_functions;
    std::map<unsigned int, std::shared_ptr<FunctionParser<dim>>>
                                                      pressure_functions;
    std::vector<std::shared_ptr<FunctionParser<dim>>> body_force_functions;
    /// Per Dirichlet tag that moves: its displacement as a function of x
    /// and t.
    std::map<unsigned int, std::shared_ptr<FunctionParser<dim>>>
      prescribed_functions;
    /// the load functions above that depend on t
    std::set<const Function<dim> *> load_functions_of_time;
    Tensor<1, dim>                  traction;
    Tensor<1, dim>                  gravity;
  };
} // namespace dyncontact

#endif
