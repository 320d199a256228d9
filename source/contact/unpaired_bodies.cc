// The watch over bodies that no contact pair holds apart.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <dyncontact/contact/contact_search.h>
#include <dyncontact/contact/unpaired_bodies.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace dyncontact
{
  template <int dim>
  UnpairedBodies<dim>::UnpairedBodies(const MPI_Comm comm)
    : comm(comm)
  {}



  template <int dim>
  void
  UnpairedBodies<dim>::setup(const std::vector<ContactPair> &pairs,
                             const unsigned int              n_bodies,
                             const SemiDiscreteSystem<dim>  &system,
                             const Mapping<dim>             &mapping)
  {
    body_pairs.clear();
    faces.clear();
    nodes.clear();
    if (n_bodies < 2)
      return;
    const auto &dof_handler = system.get_dof_handler();
    const auto  ids =
      boundary_ids_of_bodies(dof_handler.get_triangulation(), n_bodies);
    std::set<std::pair<unsigned int, unsigned int>> joined;
    for (const ContactPair &pair : pairs)
      for (unsigned int a = 0; a < n_bodies; ++a)
        for (unsigned int b = 0; b < n_bodies; ++b)
          if (has_any_of(ids[a], pair.first_side) &&
              has_any_of(ids[b], pair.second_side))
            joined.insert({std::min(a, b), std::max(a, b)});
    std::vector<bool> watched(n_bodies, false);
    for (unsigned int a = 0; a < n_bodies; ++a)
      for (unsigned int b = a + 1; b < n_bodies; ++b)
        if (joined.count({a, b}) == 0)
          {
            body_pairs.emplace_back(a, b);
            watched[a] = watched[b] = true;
          }
    if (body_pairs.empty())
      return;

    locally_owned    = system.locally_owned_dofs();
    locally_relevant = system.locally_relevant_dofs();
    faces.assign(n_bodies, {});
    nodes.assign(n_bodies, {});
    const auto &fe          = system.get_fe();
    const auto &scalar_fe   = system.get_scalar_fe();
    const auto &unit_points = scalar_fe.get_unit_support_points();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    std::set<types::global_dof_index>    seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && watched[cell->material_id()])
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const unsigned int body = cell->material_id();
              const auto         face = cell->face(f);
              MasterFace<dim>    master;
              for (const unsigned int v : face->vertex_indices())
                master.vertices.push_back(face->vertex(v));
              master.cell_center = cell->center();
              master.vertex_dofs.assign(face->n_vertices() * dim,
                                        numbers::invalid_dof_index);
              face->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const auto [c, node] = fe.face_system_to_component_index(i);
                  if (node < face->n_vertices())
                    master.vertex_dofs[node * dim + c] = face_dofs[i];
                }
              faces[body].push_back(master);

              cell->get_dof_indices(dofs);
              for (unsigned int node = 0; node < scalar_fe.n_dofs_per_cell();
                   ++node)
                if (scalar_fe.has_support_on_face(node, f))
                  {
                    Node boundary_node;
                    for (unsigned int d = 0; d < dim; ++d)
                      boundary_node.dofs[d] =
                        dofs[system.get_node_system_indices()[node][d]];
                    if (!locally_owned.is_element(boundary_node.dofs[0]) ||
                        !seen.insert(boundary_node.dofs[0]).second)
                      continue;
                    boundary_node.x =
                      mapping.transform_unit_to_real_cell(cell,
                                                          unit_points[node]);
                    nodes[body].push_back(boundary_node);
                  }
            }
  }



  template <int dim>
  typename UnpairedBodies<dim>::Overlap
  UnpairedBodies<dim>::deepest(const VectorType &u) const
  {
    Overlap deepest;
    if (body_pairs.empty())
      return deepest;
    const unsigned int n_bodies = nodes.size();
    const auto         moved    = [&](const Node &node) {
      Point<dim> y = node.x;
      for (unsigned int d = 0; d < dim; ++d)
        y[d] += u(node.dofs[d]);
      return y;
    };

    // the deformed boxes of the bodies: -lower and upper corners, for one
    // maximum over the ranks
    std::vector<double> corners(2 * dim * n_bodies,
                                -std::numeric_limits<double>::max());
    for (unsigned int b = 0; b < n_bodies; ++b)
      for (const Node &node : nodes[b])
        {
          const Point<dim> y = moved(node);
          for (unsigned int d = 0; d < dim; ++d)
            {
              double &lower = corners[(2 * b) * dim + d];
              double &upper = corners[(2 * b + 1) * dim + d];
              lower         = std::max(lower, -y[d]);
              upper         = std::max(upper, y[d]);
            }
        }
    Utilities::MPI::max(corners, comm, corners);
    // (a body that is paired with every other has no nodes here, and no
    // box)
    std::vector<BoundingBox<dim>> boxes(n_bodies);
    double                        size = 0.;
    for (unsigned int b = 0; b < n_bodies; ++b)
      {
        Point<dim> lower, upper;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = -corners[(2 * b) * dim + d];
            upper[d] = corners[(2 * b + 1) * dim + d];
          }
        if (lower[0] <= upper[0])
          {
            boxes[b] = BoundingBox<dim>({lower, upper});
            size     = std::max(size, lower.distance(upper));
          }
      }
    // (round-off of bodies that touch is no overlap)
    const double tolerance = 1e-9 * size;
    const auto   meet      = [&](const unsigned int a, const unsigned int b) {
      for (unsigned int d = 0; d < dim; ++d)
        if (boxes[a].lower_bound(d) > boxes[b].upper_bound(d) + tolerance ||
            boxes[b].lower_bound(d) > boxes[a].upper_bound(d) + tolerance)
          return false;
      return true;
    };

    VectorType ghosted;
    for (const auto &[a, b] : body_pairs)
      if (meet(a, b))
        {
          if (ghosted.size() == 0)
            {
              ghosted.reinit(locally_owned, locally_relevant, comm);
              ghosted = u;
            }
          for (const auto &[body, other] :
               {std::make_pair(a, b), std::make_pair(b, a)})
            {
              // this rank's faces of the other body, deformed, and its
              // nodes of the body in the other's box
              std::vector<MasterFace<dim>> deformed = faces[other];
              deform(deformed, ghosted);
              std::vector<Point<dim>>   points;
              std::vector<const Node *> of_points;
              BoundingBox<dim>          box = boxes[other];
              box.extend(tolerance);
              for (const Node &node : nodes[body])
                if (const Point<dim> y = moved(node); box.point_inside(y))
                  {
                    points.push_back(y);
                    of_points.push_back(&node);
                  }
              const ContactMapping<dim> phi(
                closest_faces(deformed, points, comm), 0.);
              for (unsigned int p = 0; p < points.size(); ++p)
                {
                  const auto image = phi.find_closest(points[p]);
                  if (image &&
                      (points[p] - image->point) * image->master_normal < 0. &&
                      image->gap > std::max(deepest.depth, tolerance))
                    {
                      deepest.depth    = image->gap;
                      deepest.position = of_points[p]->x;
                      deepest.body     = body;
                      deepest.other    = other;
                    }
                }
            }
        }

    // the deepest over all ranks
    std::vector<double> data(dim + 2, 0.);
    for (unsigned int d = 0; d < dim; ++d)
      data[d] = deepest.position[d];
    data[dim]     = deepest.body;
    data[dim + 1] = deepest.other;
    deepest_over_ranks(deepest.depth, data, comm);
    for (unsigned int d = 0; d < dim; ++d)
      deepest.position[d] = data[d];
    deepest.body  = std::lround(data[dim]);
    deepest.other = std::lround(data[dim + 1]);
    return deepest;
  }



  template class UnpairedBodies<2>;
  template class UnpairedBodies<3>;
} // namespace dyncontact
