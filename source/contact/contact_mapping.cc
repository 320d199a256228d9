#include <deal.II/base/exceptions.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/numerics/rtree.h>

#include <dyncontact/contact/contact_mapping.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace dyncontact
{
  namespace
  {
    /// Bilinear (2D: linear) shape functions of the face's vertices.
    template <int dim>
    Point<dim>
    face_point(const std::vector<Point<dim>> &v, const Point<dim - 1> &xi)
    {
      if constexpr (dim == 2)
        return Point<dim>(v[0] * (1. - xi[0]) + v[1] * xi[0]);
      else
        return Point<dim>(
          v[0] * ((1. - xi[0]) * (1. - xi[1])) + v[1] * (xi[0] * (1. - xi[1])) +
          v[2] * ((1. - xi[0]) * xi[1]) + v[3] * (xi[0] * xi[1]));
    }

    /// Tangent vectors d x / d xi_k.
    template <int dim>
    std::array<Tensor<1, dim>, dim - 1>
    face_tangents(const std::vector<Point<dim>> &v, const Point<dim - 1> &xi)
    {
      std::array<Tensor<1, dim>, dim - 1> t;
      if constexpr (dim == 2)
        t[0] = v[1] - v[0];
      else
        {
          t[0] = (v[1] - v[0]) * (1. - xi[1]) + (v[3] - v[2]) * xi[1];
          t[1] = (v[2] - v[0]) * (1. - xi[0]) + (v[3] - v[1]) * xi[0];
        }
      return t;
    }

    /// Unit normal of the face at xi, pointing away from the cell centre.
    template <int dim>
    Tensor<1, dim>
    outward_normal(const MasterFace<dim> &face, const Point<dim - 1> &xi)
    {
      const auto     t = face_tangents(face.vertices, xi);
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          n[0] = t[0][1];
          n[1] = -t[0][0];
        }
      else
        n = cross_product_3d(t[0], t[1]);
      n /= n.norm();
      if ((face_point(face.vertices, xi) - face.cell_center) * n < 0.)
        n *= -1.;
      return n;
    }

    /// A key for a vertex position, equal for vertices at the same place.
    std::array<long long, 3>
    vertex_key(const double *x, const unsigned int dim, const double scale)
    {
      std::array<long long, 3> key{{0, 0, 0}};
      for (unsigned int d = 0; d < dim; ++d)
        key[d] = std::llround(x[d] / scale * 1e8);
      return key;
    }
  } // namespace



  template <int dim>
  Point<dim - 1>
  closest_point_on_face(const std::vector<Point<dim>> &v,
                        const Point<dim>              &x,
                        std::array<bool, 4>           &clamped)
  {
    clamped = {{false, false, false, false}};
    Point<dim - 1> xi;
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> t = v[1] - v[0];
        double               s = ((x - v[0]) * t) / (t * t);
        if (s <= 0.)
          {
            s          = 0.;
            clamped[0] = true;
          }
        else if (s >= 1.)
          {
            s          = 1.;
            clamped[1] = true;
          }
        xi[0] = s;
      }
    else
      {
        // projected Gauss-Newton on the bilinear patch, xi in [0,1]^2
        xi = Point<dim - 1>(0.5, 0.5);
        for (unsigned int it = 0; it < 50; ++it)
          {
            const auto           t   = face_tangents(v, xi);
            const Tensor<1, dim> r   = face_point(v, xi) - x;
            const double         a11 = t[0] * t[0], a12 = t[0] * t[1],
                         a22  = t[1] * t[1];
            const double   b1 = -(t[0] * r), b2 = -(t[1] * r);
            const double   det = a11 * a22 - a12 * a12;
            double         d1  = (a22 * b1 - a12 * b2) / det;
            double         d2  = (a11 * b2 - a12 * b1) / det;
            Point<dim - 1> next(std::clamp(xi[0] + d1, 0., 1.),
                                std::clamp(xi[1] + d2, 0., 1.));
            // on a clamped side, minimise along the remaining direction
            if (next[0] == 0. || next[0] == 1.)
              next[1] = std::clamp(xi[1] + b2 / a22, 0., 1.);
            if (next[1] == 0. || next[1] == 1.)
              next[0] = std::clamp(xi[0] + b1 / a11, 0., 1.);
            const double step = (next - xi).norm();
            xi                = next;
            if (step < 1e-14)
              break;
          }
        clamped = {{xi[0] <= 0., xi[0] >= 1., xi[1] <= 0., xi[1] >= 1.}};
      }
    return xi;
  }



  template <int dim>
  BoundingBox<dim>
  search_box(const Point<dim> &x, const double radius)
  {
    Point<dim> lower = x, upper = x;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] -= radius;
        upper[d] += radius;
      }
    return BoundingBox<dim>(std::make_pair(lower, upper));
  }



  template <int dim>
  double
  box_distance(const BoundingBox<dim> &box, const Point<dim> &x)
  {
    const auto [lower, upper] = box.get_boundary_points();
    double squared            = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double outside = std::max({lower[d] - x[d], x[d] - upper[d], 0.});
        squared += outside * outside;
      }
    return std::sqrt(squared);
  }



  template <int dim>
  struct ContactMapping<dim>::Tree
  {
    RTree<std::pair<BoundingBox<dim>, unsigned int>> rtree;
  };



  template <int dim>
  ContactMapping<dim>::ContactMapping(const std::vector<MasterFace<dim>> &faces,
                                      const double search_radius)
    : master_faces(faces)
    , rim(faces.size())
    , radius(search_radius)
    , tree(std::make_unique<Tree>())
  {
    // the rim of the master surface: vertices (2D) or edges (3D) that belong
    // to a single master face and do not lie on a plane of symmetry
    double scale = 0.;
    for (const auto &face : faces)
      scale = std::max(scale, face.vertices[0].distance(face.vertices.back()));
    if (scale == 0.)
      scale = 1.;
    max_face_size = scale;
    using Key     = std::array<long long, 3>;
    auto key      = [&](const Point<dim> &p) {
      double x[3] = {0., 0., 0.};
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = p[d];
      return vertex_key(x, dim, scale);
    };
    const auto                                  sides = face_sides<dim>();
    std::map<std::pair<Key, Key>, unsigned int> count;
    auto side_key = [&](const MasterFace<dim> &face, const unsigned int s) {
      Key a = key(face.vertices[sides[s][0]]),
          b = key(face.vertices[sides[s][1]]);
      return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    };
    for (const auto &face : faces)
      for (unsigned int s = 0; s < sides.size(); ++s)
        ++count[side_key(face, s)];
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        rim[f] = {{false, false, false, false}};
        for (unsigned int s = 0; s < sides.size(); ++s)
          rim[f][s] = (count[side_key(faces[f], s)] == 1) &&
                      !faces[f].on_symmetry_plane[s];
      }

    std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
    for (unsigned int f = 0; f < faces.size(); ++f)
      boxes.emplace_back(BoundingBox<dim>(faces[f].vertices), f);
    tree->rtree = pack_rtree(boxes);
  }



  template <int dim>
  ContactMapping<dim>::~ContactMapping() = default;



  template <int dim>
  std::optional<Image<dim>>
  ContactMapping<dim>::find_image(const Point<dim> &x) const
  {
    return closest_image(x, radius);
  }



  template <int dim>
  std::optional<Image<dim>>
  ContactMapping<dim>::find_closest(const Point<dim> &x) const
  {
    if (master_faces.empty())
      return {};
    // the face of the nearest bounding box bounds the distance from above;
    // every face at most that far is then a candidate
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> nearest;
    tree->rtree.query(boost::geometry::index::nearest(x, 1),
                      std::back_inserter(nearest));
    std::array<bool, 4> clamped;
    const auto         &vertices = master_faces[nearest[0].second].vertices;
    const double        bound    = x.distance(
      face_point(vertices, closest_point_on_face(vertices, x, clamped)));
    return closest_image(x, bound * (1. + 1e-12) + 1e-300);
  }



  template <int dim>
  double
  ContactMapping<dim>::distance(const Point<dim> &x) const
  {
    double best = std::numeric_limits<double>::infinity();
    if (master_faces.empty())
      return best;
    auto face_distance = [&](const unsigned int f) {
      std::array<bool, 4> clamped;
      const auto         &vertices = master_faces[f].vertices;
      return x.distance(
        face_point(vertices, closest_point_on_face(vertices, x, clamped)));
    };
    // the face of the nearest bounding box bounds the distance from above
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> nearest;
    tree->rtree.query(boost::geometry::index::nearest(x, 1),
                      std::back_inserter(nearest));
    best = face_distance(nearest[0].second);
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> candidates;
    tree->rtree.query(boost::geometry::index::intersects(search_box(x, best)),
                      std::back_inserter(candidates));
    for (const auto &candidate : candidates)
      best = std::min(best, face_distance(candidate.second));
    return best;
  }



  template <int dim>
  std::vector<unsigned int>
  ContactMapping<dim>::faces_within(const Point<dim> &x,
                                    const double      max_distance) const
  {
    std::vector<unsigned int> within;
    if (master_faces.empty())
      return within;
    const double reach = max_distance * (1. + 1e-10) + 1e-10 * max_face_size;
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> candidates;
    tree->rtree.query(boost::geometry::index::intersects(search_box(x, reach)),
                      std::back_inserter(candidates));
    // by the distance to the face's bounding box, a lower bound of the
    // distance to the face: a projection that stops short on a warped face
    // cannot drop a face that holds the closest point
    for (const auto &candidate : candidates)
      {
        const auto &vertices = master_faces[candidate.second].vertices;
        if (box_distance(candidate.first, x) <=
            max_distance * (1. + 1e-10) +
              1e-10 * vertices[0].distance(vertices.back()))
          within.push_back(candidate.second);
      }
    std::sort(within.begin(), within.end());
    return within;
  }



  template <int dim>
  std::optional<Image<dim>>
  ContactMapping<dim>::closest_image(const Point<dim> &x,
                                     const double      max_distance) const
  {
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> candidates;
    tree->rtree.query(boost::geometry::index::intersects(
                        search_box(x, max_distance)),
                      std::back_inserter(candidates));

    std::optional<Image<dim>> best;
    bool                      best_on_rim = false;
    for (const auto &candidate : candidates)
      {
        const unsigned int   f = candidate.second;
        std::array<bool, 4>  clamped;
        const Point<dim - 1> xi =
          closest_point_on_face(master_faces[f].vertices, x, clamped);
        const Point<dim> p        = face_point(master_faces[f].vertices, xi);
        const double     distance = x.distance(p);
        if (distance > max_distance)
          continue;
        if (best && distance >= best->gap)
          continue;
        Image<dim> image;
        image.face            = f;
        image.reference_point = xi;
        image.point           = p;
        image.gap             = distance;
        image.master_normal   = outward_normal(master_faces[f], xi);
        best                  = image;
        best_on_rim           = false;
        for (unsigned int s = 0; s < 4; ++s)
          if (clamped[s] && rim[f][s])
            best_on_rim = true;
      }
    if (!best)
      return best;

    const double size = master_faces[best->face].vertices[0].distance(
      master_faces[best->face].vertices.back());
    const bool touching = best->gap <= 1e-10 * size;
    // the image lies outside the master surface (on its rim, at a distance,
    // and not along the surface normal)
    if (best_on_rim && !touching)
      {
        const Tensor<1, dim> direction = (x - best->point) / best->gap;
        if (std::abs(direction * best->master_normal) < 1. - 1e-8)
          return {};
      }
    // eq. (3): nu = (phi(x) - x)/|phi(x) - x|, or the slave's outward normal
    // (= minus the master's) where the two coincide
    best->normal = touching ? Tensor<1, dim>(-best->master_normal) :
                              Tensor<1, dim>((best->point - x) / best->gap);
    return best;
  }



  template <int dim>
  ContactRow
  make_two_body_row(const Point<dim>                        &x,
                    const std::array<global_dof_index, dim> &slave_dofs,
                    const Image<dim>                        &image,
                    const MasterFace<dim>                   &face,
                    const unsigned int                       degree)
  {
    ContactRow row;
    row.n_components = dim;
    row.gap          = image.gap;
    for (unsigned int d = 0; d < dim; ++d)
      {
        row.entries.emplace_back(slave_dofs[d], image.normal[d]);
        row.normal[d]   = image.normal[d];
        row.position[d] = x[d];
      }
    // master entries: -N_j(phi(x)) nu_c for every DoF node j stands for
    const FE_Q<dim - 1>                face_fe(degree);
    std::map<global_dof_index, double> master;
    for (unsigned int j = 0; j < face.node_dofs.size(); ++j)
      {
        const double N = face_fe.shape_value(j, image.reference_point);
        if (std::abs(N) < 1e-14)
          continue;
        for (unsigned int c = 0; c < dim; ++c)
          for (const auto &[dof, weight] : face.node_dofs[j][c])
            master[dof] -= N * image.normal[c] * weight;
        if (face.node_dof0[j] != numbers::invalid_dof_index)
          row.master_nodes.emplace_back(face.node_dof0[j], N);
      }
    for (const auto &[dof, coefficient] : master)
      if (std::abs(coefficient) > 1e-14)
        row.entries.emplace_back(dof, coefficient);
    return row;
  }

  template BoundingBox<2>
  search_box(const Point<2> &, const double);
  template BoundingBox<3>
  search_box(const Point<3> &, const double);
  template double
  box_distance(const BoundingBox<2> &, const Point<2> &);
  template double
  box_distance(const BoundingBox<3> &, const Point<3> &);
  template Point<1>
  closest_point_on_face<2>(const std::vector<Point<2>> &,
                           const Point<2> &,
                           std::array<bool, 4> &);
  template Point<2>
  closest_point_on_face<3>(const std::vector<Point<3>> &,
                           const Point<3> &,
                           std::array<bool, 4> &);
  template class ContactMapping<2>;
  template class ContactMapping<3>;
  template ContactRow
  make_two_body_row<2>(const Point<2> &,
                       const std::array<global_dof_index, 2> &,
                       const Image<2> &,
                       const MasterFace<2> &,
                       const unsigned int);
  template ContactRow
  make_two_body_row<3>(const Point<3> &,
                       const std::array<global_dof_index, 3> &,
                       const Image<3> &,
                       const MasterFace<3> &,
                       const unsigned int);
} // namespace dyncontact
