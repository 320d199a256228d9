#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/checksum.h>
#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/body_overlap.h>
#include <dyncontact/scenes/gmsh_scene.h>
#include <dyncontact/scenes/msh_check.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_set>

namespace dyncontact
{
  namespace
  {
    std::string
    to_list(const std::set<unsigned int> &tags)
    {
      std::string text;
      for (const auto tag : tags)
        text += (text.empty() ? "" : ", ") + std::to_string(tag);
      return text;
    }

    /// The cell tags of each body, as the prm gives them, for messages.
    std::string
    bodies_text(const std::vector<std::set<unsigned int>> &body_tags,
                const bool                                 listed)
    {
      if (!listed)
        return "Scene/Gmsh/Body 1 tags = " + to_list(body_tags[0]) +
               ", Scene/Gmsh/Body 2 tags = " +
               (body_tags.size() > 1 ? to_list(body_tags[1]) : "");
      std::string text = "Scene/Gmsh/Bodies = ";
      for (unsigned int b = 0; b < body_tags.size(); ++b)
        text += (b > 0 ? "; " : "") + to_list(body_tags[b]);
      return text;
    }

    /**
     * The body whose tags in @p body_tags contain the physical tag @p tag
     * of a cell; throws if none does.
     */
    unsigned int
    body_of_cell_tag(const unsigned int                         tag,
                     const std::vector<std::set<unsigned int>> &body_tags,
                     const bool                                 listed,
                     const std::string                         &mesh_file)
    {
      int body = -1;
      for (unsigned int b = 0; b < body_tags.size(); ++b)
        if (body_tags[b].count(tag))
          body = b;
      AssertThrow(body >= 0,
                  ExcMessage("Mesh file '" + mesh_file +
                             "': cells with physical tag " +
                             std::to_string(tag) + " belong to no body (" +
                             bodies_text(body_tags, listed) + ")."));
      return body;
    }

    /**
     * Replaces the physical tag (material id) of every cell of @p tria by
     * the number of its body. Checks that the bodies share no vertex and
     * that the mesh has cells with every tag in @p body_tags; @p listed:
     * the bodies were given by Bodies (else by Body 1 and 2 tags), for
     * messages.
     */
    template <int dim>
    void
    set_bodies(Triangulation<dim, dim>                   &tria,
               const std::vector<std::set<unsigned int>> &body_tags,
               const bool                                 listed,
               const std::string                         &mesh_file)
    {
      std::set<unsigned int>               cell_tags;
      std::map<unsigned int, unsigned int> vertex_body;
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int tag = cell->material_id();
          cell_tags.insert(tag);
          const unsigned int body =
            body_of_cell_tag(tag, body_tags, listed, mesh_file);
          cell->set_material_id(body);
          for (const auto v : cell->vertex_indices())
            {
              const auto [it, inserted] =
                vertex_body.emplace(cell->vertex_index(v), body);
              AssertThrow(inserted || it->second == body,
                          ExcMessage(
                            "Mesh file '" + mesh_file + "': bodies " +
                            std::to_string(it->second + 1) + " and " +
                            std::to_string(body + 1) + " share the vertex " +
                            Utilities::to_string(cell->vertex(v)[0]) + ", " +
                            Utilities::to_string(cell->vertex(v)[1]) +
                            "; bodies in contact must be meshed "
                            "separately."));
            }
        }
      // the pieces of each body: cells joined by shared vertices (the
      // coarse mesh is whole on every rank)
      std::vector<unsigned int> parent(tria.n_vertices());
      std::iota(parent.begin(), parent.end(), 0u);
      const auto root = [&](unsigned int v) {
        while (parent[v] != v)
          v = parent[v] = parent[parent[v]];
        return v;
      };
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto v : cell->vertex_indices())
          parent[root(cell->vertex_index(v))] = root(cell->vertex_index(0));
      std::vector<std::set<unsigned int>> pieces(body_tags.size());
      for (const auto &cell : tria.active_cell_iterators())
        pieces[cell->material_id()].insert(root(cell->vertex_index(0)));
      for (unsigned int b = 0; b < body_tags.size(); ++b)
        if (pieces[b].size() > 1 &&
            Utilities::MPI::this_mpi_process(tria.get_communicator()) == 0)
          std::cout << "   warning: body " << b + 1 << " of mesh file '"
                    << mesh_file << "' is made of " << pieces[b].size()
                    << " disconnected pieces: they move as parts of one "
                       "body and never touch each other (no contact is "
                       "sought between them). If they are separate bodies, "
                       "give each its own entry (bodies are separated by ';' "
                       "in Scene/Gmsh/Bodies)."
                    << std::endl;
      for (unsigned int b = 0; b < body_tags.size(); ++b)
        for (const auto tag : body_tags[b])
          AssertThrow(cell_tags.count(tag),
                      ExcMessage((!listed ? "Scene/Gmsh/Body " +
                                              std::to_string(b + 1) + " tags" :
                                            "Scene/Gmsh/Bodies (body " +
                                              std::to_string(b + 1) + ")") +
                                 ": the mesh file '" + mesh_file +
                                 "' has no cells with physical tag " +
                                 std::to_string(tag) + "."));
    }

    /**
     * Stops with a message if two bodies of @p tria (material ids: bodies)
     * that no pair of @p paired holds apart overlap: a vertex or a cell
     * centre of one lies strictly inside a cell of the other (a point on
     * the other's boundary, where bodies touch, does not count). Checked
     * on the coarse mesh, which every rank holds whole, where the bodies'
     * bounding boxes meet; the cells of the finer meshes lie in their
     * coarse cells.
     */
    template <int dim>
    void
    refuse_overlap_of_unpaired_bodies(
      const Triangulation<dim, dim>                         &tria,
      const unsigned int                                     n_bodies,
      const std::set<std::pair<unsigned int, unsigned int>> &paired,
      const std::string                                     &mesh_file)
    {
      using Box = BoundingBox<dim>;
      std::vector<std::vector<typename Triangulation<dim>::cell_iterator>>
                        cells(n_bodies);
      std::vector<Box>  body_box(n_bodies);
      std::vector<bool> has_box(n_bodies, false);
      for (const auto &cell : tria.cell_iterators_on_level(0))
        {
          const unsigned int b = cell->material_id();
          cells[b].push_back(cell);
          const Box box = cell->bounding_box();
          if (has_box[b])
            body_box[b].merge_with(box);
          else
            body_box[b] = box;
          has_box[b] = true;
        }
      for (unsigned int a = 0; a < n_bodies; ++a)
        for (unsigned int b = 0; b < n_bodies; ++b)
          if (a != b && has_box[a] && has_box[b] &&
              paired.count({std::min(a, b), std::max(a, b)}) == 0 &&
              body_box[a].get_neighbor_type(body_box[b]) !=
                NeighborType::not_neighbors)
            {
              // the cells of b near a, and the points of a near b
              std::vector<unsigned int> near;
              for (unsigned int c = 0; c < cells[b].size(); ++c)
                if (cells[b][c]->bounding_box().get_neighbor_type(
                      body_box[a]) != NeighborType::not_neighbors)
                  near.push_back(c);
              for (const auto &cell : cells[a])
                {
                  std::vector<Point<dim>> points = {cell->center()};
                  for (const auto v : cell->vertex_indices())
                    points.push_back(cell->vertex(v));
                  for (const Point<dim> &x : points)
                    for (const unsigned int c : near)
                      if (strictly_inside<dim>(cells[b][c], x))
                        {
                          std::ostringstream where;
                          for (unsigned int d = 0; d < dim; ++d)
                            where << (d > 0 ? ", " : "") << x[d];
                          AssertThrow(
                            false,
                            ExcMessage(
                              "Mesh file '" + mesh_file + "': bodies " +
                              std::to_string(a + 1) + " and " +
                              std::to_string(b + 1) +
                              " overlap at t = 0 (the point (" + where.str() +
                              ") of body " + std::to_string(a + 1) +
                              " lies inside body " + std::to_string(b + 1) +
                              "), and no contact pair holds them apart: "
                              "correct the mesh, or pair them in "
                              "Scene/Gmsh/Contact pairs."));
                        }
                }
            }
    }



    /**
     * The physical tags of the boundary faces of @p tria (whose material
     * ids are bodies, see set_bodies()). Checks that the faces with a tag in
     * @p contact_tags[b] lie on body b.
     */
    template <int dim>
    std::set<unsigned int>
    boundary_tags(
      const Triangulation<dim, dim>                      &tria,
      const std::vector<std::vector<types::boundary_id>> &contact_tags,
      const std::vector<std::string>                     &entries,
      const std::string                                  &mesh_file)
    {
      std::set<unsigned int> face_tags;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const unsigned int tag = cell->face(f)->boundary_id();
              face_tags.insert(tag);
              for (unsigned int b = 0; b < contact_tags.size(); ++b)
                AssertThrow(std::find(contact_tags[b].begin(),
                                      contact_tags[b].end(),
                                      tag) == contact_tags[b].end() ||
                              cell->material_id() == b,
                            ExcMessage(
                              "Scene/Gmsh/" + entries[b] +
                              ": the boundary faces "
                              "with physical tag " +
                              std::to_string(tag) + " in the mesh file '" +
                              mesh_file + "' belong to body " +
                              std::to_string(cell->material_id() + 1) +
                              ", not to body " + std::to_string(b + 1) + "."));
            }
      return face_tags;
    }

    /// A tag itself, or the key of a (tag, data) pair of a map.
    inline unsigned int
    tag_of(const unsigned int tag)
    {
      return tag;
    }
    template <typename Data>
    unsigned int
    tag_of(const std::pair<const unsigned int, Data> &item)
    {
      return item.first;
    }

    /**
     * Checks that @p face_tags (the tags of the boundary faces) has every
     * tag in @p tags (tags, or a map from tags), the value of the parameter
     * Scene/Gmsh/@p entry.
     */
    template <typename Tags>
    void
    require_boundary_tags(const std::set<unsigned int> &face_tags,
                          const std::string            &entry,
                          const Tags                   &tags,
                          const std::string            &mesh_file)
    {
      for (const auto &item : tags)
        {
          const unsigned int tag = tag_of(item);
          AssertThrow(face_tags.count(tag),
                      ExcMessage("Scene/Gmsh/" + entry + ": the mesh file '" +
                                 mesh_file +
                                 "' has no boundary faces with physical tag " +
                                 std::to_string(tag) + "."));
        }
    }
  } // namespace



  template <int dim>
  void
  GmshScene<dim>::create_coarse_mesh(Triangulation<dim, dim> &tria) const
  {
    std::ifstream in(mesh_file);
    GridIn<dim>   grid_in;
    grid_in.attach_triangulation(tria);
    grid_in.read_msh(in);

    set_bodies(tria, body_tags, pairs_listed, mesh_file);
    std::set<std::pair<unsigned int, unsigned int>> paired;
    for (const BodyPair &pair : pairs)
      paired.insert(
        {std::min(pair.slave, pair.master), std::max(pair.slave, pair.master)});
    refuse_overlap_of_unpaired_bodies(tria,
                                      body_tags.size(),
                                      paired,
                                      mesh_file);
    const auto face_tags =
      boundary_tags(tria, contact_tags, contact_entries, mesh_file);
    require_boundary_tags(face_tags,
                          "Dirichlet tags",
                          dirichlet_components,
                          mesh_file);
    require_boundary_tags(face_tags, "Neumann tags", neumann_tags, mesh_file);
    require_boundary_tags(face_tags,
                          "Neumann tractions",
                          tag_tractions,
                          mesh_file);
    require_boundary_tags(face_tags,
                          "Neumann tractions",
                          traction_functions,
                          mesh_file);
    require_boundary_tags(face_tags,
                          "Pressures",
                          pressure_functions,
                          mesh_file);
    for (unsigned int b = 0; b < contact_tags.size(); ++b)
      require_boundary_tags(face_tags,
                            contact_entries[b],
                            contact_tags[b],
                            mesh_file);
    attach_manifolds(tria, face_tags);
  }



  template <int dim>
  std::vector<ContactPair>
  GmshScene<dim>::contact_pairs() const
  {
    std::vector<ContactPair> result;
    for (const BodyPair &body_pair : pairs)
      {
        ContactPair pair;
        pair.first_side  = body_pair.slave_tags;
        pair.second_side = body_pair.master_tags;
        // Body 1 tags and Body 2 tags: Contact/Slave side decides (auto:
        // the finer side); a list of pairs names the slave
        if (pairs_listed)
          {
            pair.slave_side     = 0;
            pair.own_slave_side = true;
          }
        pair.search_radius     = body_pair.search_radius;
        pair.own_search_radius = body_pair.search_radius > 0.;
        result.push_back(pair);
      }
    return result;
  }



  template <int dim>
  std::vector<types::boundary_id>
  GmshScene<dim>::contact_boundary_ids() const
  {
    std::set<types::boundary_id> ids;
    for (const auto &tags : obstacle_tags)
      ids.insert(tags.begin(), tags.end());
    return {ids.begin(), ids.end()};
  }



  template <int dim>
  std::vector<DirichletBoundary>
  GmshScene<dim>::dirichlet_boundaries() const
  {
    std::vector<DirichletBoundary> boundaries;
    for (const auto &[tag, components] : dirichlet_components)
      boundaries.push_back({types::boundary_id(tag), components});
    return boundaries;
  }



  template <int dim>
  std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
  GmshScene<dim>::neumann_tractions() const
  {
    std::vector<std::pair<types::boundary_id, Tensor<1, dim>>> tractions;
    for (const auto tag : neumann_tags)
      tractions.emplace_back(tag, traction);
    for (const auto &[tag, value] : tag_tractions)
      tractions.emplace_back(tag, value);
    return tractions;
  }



  template <int dim>
  Tensor<1, dim>
  GmshScene<dim>::body_force(const unsigned int body) const
  {
    return this->material(body).density * gravity;
  }



  namespace
  {
    /// Stops with a message naming Scene/Gmsh/@p entry unless @p value is
    /// finite.
    template <int dim>
    void
    refuse_non_finite(const Tensor<1, dim> &value,
                      const std::string    &entry,
                      const Point<dim>     &x)
    {
      bool finite = true;
      for (unsigned int d = 0; d < dim; ++d)
        finite = finite && std::isfinite(value[d]);
      if (finite)
        return;
      std::ostringstream where;
      for (unsigned int d = 0; d < dim; ++d)
        where << (d > 0 ? ", " : "") << x[d];
      AssertThrow(false,
                  ExcMessage("Scene/Gmsh/" + entry +
                             " is not finite at the node (" + where.str() +
                             ")."));
    }
  } // namespace



  template <int dim>
  Tensor<1, dim>
  GmshScene<dim>::initial_velocity(const Point<dim>  &x,
                                   const unsigned int body) const
  {
    if (velocity_functions.empty())
      return velocity[body];
    Tensor<1, dim> v;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] = velocity_functions[body]->value(x, d);
    refuse_non_finite(v, "Initial velocity", x);
    return v;
  }



  template <int dim>
  Tensor<1, dim>
  GmshScene<dim>::initial_displacement(const Point<dim>  &x,
                                       const unsigned int body) const
  {
    Tensor<1, dim> u;
    if (!displacement_functions.empty())
      for (unsigned int d = 0; d < dim; ++d)
        u[d] = displacement_functions[body]->value(x, d);
    refuse_non_finite(u, "Initial displacement", x);
    return u;
  }


  DYNCONTACT_REGISTER_SCENE(GmshScene,
                            "gmsh",
                            "any mesh of one or more bodies from a .msh "
                            "file")
} // namespace dyncontact
