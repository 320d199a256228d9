#ifndef dyncontact_contact_mapping_h
#define dyncontact_contact_mapping_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dyncontact/contact/contact_rows.h>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace dyncontact
{
  using namespace dealii;

  /**
   * One face of the master contact surface, as the rank that owns its cell
   * sends it to the ranks whose slave nodes are near: its vertices (in the
   * face's own order; the face is bilinear, as MappingQ1 sees it), the centre
   * of its cell (to orient the outward normal), and for each face node
   * (FE_Q<dim-1>(p) numbering) and displacement component the unconstrained
   * DoFs it stands for (a hanging node expands into its parents, a Dirichlet
   * DoF into nothing), and which sides of the face (numbered as in
   * closest_point_on_face) lie on a plane of symmetry of the model, across
   * which the surface continues.
   */
  template <int dim>
  struct MasterFace
  {
    std::vector<Point<dim>> vertices;
    Point<dim>              cell_center;
    std::vector<
      std::array<std::vector<std::pair<global_dof_index, double>>, dim>>
                                  node_dofs;
    std::vector<global_dof_index> node_dof0;
    /// The DoFs of each vertex (dim per vertex, as the face numbers them),
    /// constrained or not: the displacement of the vertex for the deformed
    /// surface.
    std::vector<global_dof_index> vertex_dofs;
    std::array<bool, 4> on_symmetry_plane{{false, false, false, false}};

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &vertices &cell_center &node_dofs &node_dof0 &vertex_dofs
        &on_symmetry_plane;
    }
  };

  /// The closest point phi_h(x) of one slave node on the master surface.
  template <int dim>
  struct Image
  {
    unsigned int   face = 0;
    Point<dim - 1> reference_point; ///< on the face's unit cell
    Point<dim>     point;           ///< phi_h(x)
    double         gap = 0.;        ///< |x - phi_h(x)|, eq. (2)
    Tensor<1, dim> normal;          ///< nu_p, eq. (3)
    Tensor<1, dim> master_normal;   ///< outward normal of the master face
  };

  /// The sides of a face as pairs of its vertices, numbered as in
  /// closest_point_on_face: 2D vertex 0, 1; 3D xi=0 (v0,v2), xi=1 (v1,v3),
  /// eta=0 (v0,v1), eta=1 (v2,v3).
  template <int dim>
  inline std::vector<std::array<unsigned int, 2>>
  face_sides()
  {
    if (dim == 2)
      return {{{0, 0}}, {{1, 1}}};
    return {{{0, 2}}, {{1, 3}}, {{0, 1}}, {{2, 3}}};
  }

  /// Closest point of @p x on one bilinear face (segment in 2D): returns the
  /// reference point and, in @p clamped_sides, which sides of the unit cell
  /// the point is clamped to (2D: vertex 0, 1; 3D: xi=0, xi=1, eta=0, eta=1).
  /// The box of half-width @p radius around @p x.
  template <int dim>
  BoundingBox<dim>
  search_box(const Point<dim> &x, const double radius);

  /// The Euclidean distance from @p x to @p box (0 inside).
  template <int dim>
  double
  box_distance(const BoundingBox<dim> &box, const Point<dim> &x);

  template <int dim>
  Point<dim - 1>
  closest_point_on_face(const std::vector<Point<dim>> &vertices,
                        const Point<dim>              &x,
                        std::array<bool, 4>           &clamped_sides);

  /**
   * The discrete mapping phi_h onto a master surface: a search structure
   * (an R-tree of the faces' bounding boxes) and the closest-point
   * projection. find_image() gives no image for a point farther than the
   * search radius, or whose closest point lies on the rim of the master
   * surface (outside it) at a positive distance.
   */
  template <int dim>
  class ContactMapping
  {
  public:
    ContactMapping(const std::vector<MasterFace<dim>> &faces,
                   const double                        search_radius);
    ~ContactMapping();

    std::optional<Image<dim>>
    find_image(const Point<dim> &x) const;

    /// As find_image(), but at any distance: the closest point of @p x on
    /// the master surface (none if it lies beside the rim).
    std::optional<Image<dim>>
    find_closest(const Point<dim> &x) const;

    /// The distance from @p x to the closest point of the faces (infinity
    /// without faces), rim or not.
    double
    distance(const Point<dim> &x) const;

    /// The faces whose bounding box is at most @p max_distance away from
    /// @p x, up to round-off (1e-10 of the distance and of the face's size):
    /// among them every face at most that far.
    std::vector<unsigned int>
    faces_within(const Point<dim> &x, const double max_distance) const;

    const std::vector<MasterFace<dim>> &
    faces() const
    {
      return master_faces;
    }

  private:
    /// The image among the faces within @p max_distance of @p x.
    std::optional<Image<dim>>
    closest_image(const Point<dim> &x, const double max_distance) const;

    struct Tree;
    std::vector<MasterFace<dim>> master_faces;
    /// For each face: is its side (see closest_point_on_face) on the rim of
    /// the master surface, i.e. neither shared with another master face nor
    /// on a plane of symmetry?
    std::vector<std::array<bool, 4>> rim;
    double                           radius;
    double                           max_face_size = 1.;
    std::unique_ptr<Tree>            tree;
  };

  /// Builds the constraint row of a slave node at @p x with DoFs
  /// @p slave_dofs (one per component) from its image on the master surface
  /// (FE_Q<dim-1>(@p degree) shape functions at the image point).
  template <int dim>
  ContactRow
  make_two_body_row(const Point<dim>                        &x,
                    const std::array<global_dof_index, dim> &slave_dofs,
                    const Image<dim>                        &image,
                    const MasterFace<dim>                   &face,
                    const unsigned int                       degree);
} // namespace dyncontact

#endif
