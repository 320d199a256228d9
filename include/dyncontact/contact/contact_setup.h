#ifndef dyncontact_contact_contact_setup_h
#define dyncontact_contact_contact_setup_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/fe/mapping.h>

#include <dyncontact/contact/active_set_solver.h>
#include <dyncontact/contact/contact_mapping.h>
#include <dyncontact/contact/contact_rows.h>
#include <dyncontact/contact/contact_search.h>
#include <dyncontact/contact/unpaired_bodies.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/scenes/interface.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * The contact set-up on the current mesh: the constraint rows c_p . v <=
   * g_p of every slave node of the possible contact boundary, against the
   * rigid obstacle or, for two-body pairs, through the mapping phi_h onto
   * the master surface (the slave side chosen as the finer one unless the
   * prm says otherwise), and the row operator that evaluates C v. A scene
   * without contact gets no rows and no search.
   */
  template <int dim>
  class ContactSetup
  {
  public:
    /// Subsection "Contact": the prm's word on the scene's contact pairs.
    struct Parameters
    {
      /// -1: the scene's choice (automatic), 0: side 1, 1: side 2.
      int slave_side = -1;
      /// In m; 0: the scene's default.
      double search_radius = 0.;
      /// Initial penetration: reject or project an initially
      /// penetrating configuration.
      bool project_initial_penetration = false;
      /// Whether a contact pair (or the obstacle) without any row at t = 0
      /// is refused (true) or run with a warning.
      bool refuse_pair_without_rows = true;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    ContactSetup(const Parameters &parameters, const MPI_Comm comm);

    /// Checks the parameters against the scene (before any mesh is built).
    void
    check(const Scene<dim> &scene) const;

    /// The scene's contact pairs with the prm's slave side and radius (a
    /// pair with its own radius keeps it).
    std::vector<ContactPair>
    contact_pairs(const Scene<dim> &scene) const;

    /// Builds the rows on the current mesh.
    void
    setup(const Scene<dim>              &scene,
          const SemiDiscreteSystem<dim> &system,
          const Mapping<dim>            &mapping,
          const ConditionalOStream      &pcout);

    const ContactRows &
    get_rows() const
    {
      return rows;
    }

    /// With rigid obstacles that move: the rows' gaps at time @p t (also
    /// those of every later set-up, until the next call); nothing
    /// otherwise.
    void
    set_obstacle_time(const double t)
    {
      obstacle_time = t;
      if (rows.obstacles_move())
        rows.set_time(t);
    }

    /**
     * Keeps the slave sides that "Slave side = auto" chose on the current
     * mesh (the mesh at t = 0) for every later set-up, so that an adapted
     * mesh does not swap slave and master: the master nodes, which the
     * node-to-segment rows do not hold, would then stand inside the other
     * body and be pushed out at once. Saved in checkpoints.
     */
    void
    keep_slave_sides();

    void
    save(std::map<std::string, std::string> &state) const;
    /// Before the set-up of a resumed run. A checkpoint without the entry
    /// (of an older version) leaves them to be chosen on the checkpoint's
    /// mesh (and kept by keep_slave_sides() after that set-up).
    void
    load(const std::map<std::string, std::string> &state);

    /// The deepest penetration of a slave node without a constraint row.
    struct Penetration
    {
      double       depth = 0.; ///< in m; 0 if none penetrates
      Point<dim>   position;   ///< reference position of that slave node
      unsigned int pair = 0;   ///< its contact pair
      /// Whether the node has a row of another pair, of a master nearer in
      /// the reference configuration (else it is beyond the search radius).
      bool nearer_master = false;
    };

    /**
     * The slave nodes of two-body pairs that got no constraint row (farther
     * than the search radius from the master surface, or beside it) can
     * still pass into the other body if the radius was too small, and a
     * node that kept the row of a nearer master (keep_nearest_rows(): the
     * rows are chosen on the reference configuration) into the farther
     * master, a body or the rigid obstacle: this finds the deepest such
     * node, by the closest point of its deformed position x + u(x) on the
     * deformed master surface (at any distance), inside if it lies behind
     * the master face, or by its depth in the obstacle. Each rank deforms the
     * master faces of its own cells and sends to every rank only the faces
     * closest to that rank's nodes (closest_faces()). Collective; nothing
     * is done (and no communication happens) when every slave node has a
     * row in every pair it belongs to.
     */
    Penetration
    unmatched_penetration(const VectorType &u) const;

    /// The watch over the bodies that no contact pair holds apart (set up
    /// with the rows).
    const UnpairedBodies<dim> &
    get_unpaired_bodies() const
    {
      return unpaired_bodies;
    }

    /// The number of contact rows over all ranks (get_rows() holds this
    /// rank's).
    types::global_dof_index
    n_global_rows() const
    {
      return n_global_row_count;
    }

    /// The search radius (m) of pair @p pair (in the order of the
    /// statistics; 0 for the rigid obstacle, which needs none).
    double
    search_radius(const unsigned int pair) const
    {
      return pair < search_radii.size() ? search_radii[pair] : 0.;
    }

    /// The number of watched slave nodes (see unmatched_penetration(): a
    /// node without a row of a pair, counted once per pair), over all
    /// ranks.
    types::global_dof_index
    n_unmatched() const
    {
      return n_unmatched_nodes;
    }

    /// Evaluates C v and C v - g.
    const ContactRowOperator &
    get_row_operator() const
    {
      return row_operator;
    }

  private:
    /// A locally owned node on the contact boundary: its position and its
    /// DoFs.
    struct BoundaryNode
    {
      Point<dim>                               x;
      std::array<types::global_dof_index, dim> dofs;
    };

    /// The locally owned, non-hanging nodes on the boundary parts @p ids,
    /// each once, in the order of the cells.
    std::vector<BoundaryNode>
    boundary_nodes(const SemiDiscreteSystem<dim>         &system,
                   const Mapping<dim>                    &mapping,
                   const std::vector<types::boundary_id> &ids) const;

    /// Completes @p row (weight from @p w_ghosted, the eliminated
    /// component) and keeps it, unless no component of its node is free.
    void
    add_row(ContactRow                      &row,
            const VectorType                &w_ghosted,
            const AffineConstraints<double> &constraints);

    /// The rows of the nodes @p nodes against the rigid obstacle, with the
    /// pair index @p pair_index (the obstacle number @p obstacle_number
    /// from 1, for messages).
    void
    add_obstacle_rows(const RigidObstacle<dim>        &obstacle,
                      const unsigned int               obstacle_number,
                      const unsigned int               pair_index,
                      const std::vector<BoundaryNode> &nodes,
                      const VectorType                &w_ghosted,
                      const AffineConstraints<double> &constraints);

    /// Records that contact @p pair (its name) has no row at t = 0 for
    /// @p reason, with @p remedy: refuse_initial_overlap() refuses it (or
    /// warns, with 'Contact/Pair without rows = warn').
    void
    add_pair_without_rows(const std::string &pair,
                          const std::string &reason,
                          const std::string &remedy);

    /// "pair k (slave body a, master body b)" of the two-body pair
    /// @p pair_index (without the bodies in a scene of one pair), for the
    /// messages.
    std::string
    pair_name(const unsigned int pair_index) const;

    /// The messages of add_pair_without_rows() at the last set-up at t = 0.
    std::vector<std::string> pairs_without_rows;

    /// The overlap check of refuse_initial_overlap().
    void
    refuse_unmatched_overlap(const VectorType &u) const;

    /// Stops with a message naming the pair if a slave node without a row
    /// of a pair lies inside that pair's master, the other body or the
    /// rigid obstacle, in the initial state @p u (they overlap at t = 0; a
    /// node with a row is refused or projected by setup() and
    /// project_initial_penetration()). Then stops with a message naming
    /// the first contact pair (or the obstacle) without any row at t = 0
    /// and why, or warns of each with 'Contact/Pair without rows = warn'
    /// (after the overlap check: the nodes of overlapping bodies have no
    /// row either, and that message names the cause). Collective.
  public:
    void
    refuse_initial_overlap(const VectorType &u) const;

    /// Whether 'Contact/Initial penetration = project' (else: reject).
    bool
    projects_initial_penetration() const
    {
      return parameters.project_initial_penetration;
    }

  private:
    /// Of the rows of one slave node in several pairs, keeps the one with
    /// the least gap (the nearer master).
    void
    keep_nearest_rows();

    /// The side (0 or 1) of a pair whose faces near the other side are
    /// finer on average: the slave of "Slave side = auto".
    unsigned int
    finer_side(const std::array<std::vector<MasterFace<dim>>, 2> &sides,
               const double search_radius) const;

    /// The rows of the slave nodes of one two-body pair, through phi_h.
    void
    add_pair_rows(const Scene<dim>              &scene,
                  const ContactPair             &pair,
                  const unsigned int             pair_index,
                  const SemiDiscreteSystem<dim> &system,
                  const Mapping<dim>            &mapping,
                  const VectorType              &w_ghosted,
                  const ConditionalOStream      &pcout);

    /// This rank's contact faces (of its locally owned cells) with boundary
    /// ids @p ids; sides of a face shared with a boundary face of
    /// @p symmetry_ids (a plane of symmetry) are marked.
    std::vector<MasterFace<dim>>
    local_faces(const SemiDiscreteSystem<dim>         &system,
                const std::vector<types::boundary_id> &ids,
                const std::vector<types::boundary_id> &symmetry_ids) const;

    /// A locally owned slave node without a row.
    struct UnmatchedNode
    {
      Point<dim>                               x;
      std::array<types::global_dof_index, dim> dofs;
      unsigned int                             pair;
      /// Whether it kept the row of a nearer master of another pair.
      bool nearer_master = false;
    };

    const Parameters    parameters;
    const MPI_Comm      comm;
    UnpairedBodies<dim> unpaired_bodies;
    /// The mesh of the last set-up, whose coarse cells tell whether a
    /// point lies inside a body (refuse_unmatched_overlap()).
    const Triangulation<dim>  *coarse_mesh = nullptr;
    ContactRows                rows;
    types::global_dof_index    n_global_row_count = 0;
    std::vector<UnmatchedNode> unmatched;
    types::global_dof_index    n_unmatched_nodes = 0;
    /// The rigid obstacles, pairs numbered after the two-body pairs.
    std::vector<RigidObstacle<dim>> rigid_obstacles;
    /// Per pair (kept only if a slave node has no row): this rank's faces
    /// of the master surface, and the number of nodes without a row over
    /// all ranks (the last entry: the obstacle's, nodes that kept the row
    /// of a nearer master).
    std::vector<std::vector<MasterFace<dim>>> master_surfaces;
    std::vector<types::global_dof_index>      n_unmatched_in_pair;
    /// Per pair: its search radius (m), and (scenes of several pairs) the
    /// bodies of its two sides, for the banner.
    std::vector<double> search_radii;
    /// Per pair: the boundary ids of its two sides; the scene's number of
    /// bodies.
    std::vector<std::array<std::vector<types::boundary_id>, 2>> pair_sides;
    unsigned int                                                n_bodies = 0;
    std::vector<std::array<std::string, 2>>                     side_bodies;
    /// Whether the scene has more than one pair (the obstacle counted):
    /// messages and the banner number them.
    bool several_pairs = false;
    /// Whether local_faces() met a node that moves with prescribed data
    /// along its face's normal.
    mutable bool moving_contact_nodes = false;
    /// The system of the rows being set up (in setup()).
    const SemiDiscreteSystem<dim> *rows_system = nullptr;
    /// The time of the moving obstacles' gaps (set_obstacle_time()).
    double             obstacle_time = 0.;
    IndexSet           locally_owned;
    IndexSet           locally_relevant;
    ContactRowOperator row_operator;
    /// Per pair: the slave side (0, 1) of the last set-up, and those kept by
    /// keep_slave_sides() (empty: chosen anew at each set-up).
    std::vector<unsigned int> slave_sides;
    std::vector<unsigned int> kept_slave_sides;
  };
} // namespace dyncontact

#endif
