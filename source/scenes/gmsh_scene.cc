#include <deal.II/base/bounding_box.h>
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
    std::set<unsigned int>
    parse_tags(const std::string &text, const std::string &entry)
    {
      std::set<unsigned int> tags;
      for (const auto &item : Utilities::split_string_list(text, ','))
        {
          char      *end = nullptr;
          const long tag = std::strtol(item.c_str(), &end, 10);
          AssertThrow(!item.empty() && *end == '\0' && tag >= 0 && tag < 65535,
                      ExcMessage("Scene/Gmsh/" + entry +
                                 " must be a comma-separated list of "
                                 "physical tags (integers 0 to 65534); got '" +
                                 text + "'."));
          tags.insert(tag);
        }
      return tags;
    }

    /// "Dirichlet tags": a list of tags, each with the displacement
    /// components it fixes ("10, 11: y, 12: xz"; a tag alone fixes all).
    template <int dim>
    std::map<unsigned int, std::array<bool, 3>>
    parse_dirichlet_tags(const std::string &text)
    {
      std::map<unsigned int, std::array<bool, 3>> fixed;
      const std::string letters = dim == 2 ? "xy" : "xyz";
      for (const auto &item : Utilities::split_string_list(text, ','))
        {
          AssertThrow(!item.empty(),
                      ExcMessage("Scene/Gmsh/Dirichlet tags has an empty "
                                 "item (two commas in a row, or one alone) "
                                 "in '" +
                                 text + "'."));
          const auto        colon = item.find(':');
          const std::string components =
            colon == std::string::npos ? letters : item.substr(colon + 1);
          // (the tag alone, as parse_tags reads it: one integer)
          const std::string tag_text = Utilities::trim(item.substr(0, colon));
          AssertThrow(!tag_text.empty(),
                      ExcMessage("Scene/Gmsh/Dirichlet tags: '" + item +
                                 "' has no tag before ':'."));
          const unsigned int tag =
            *parse_tags(tag_text, "Dirichlet tags").begin();
          // (a tag given twice fixes what either item names)
          auto &fixed_here =
            fixed.try_emplace(tag, std::array<bool, 3>{}).first->second;
          unsigned int n = 0;
          for (const char c : components)
            if (c != ' ')
              {
                const auto d = letters.find(c);
                AssertThrow(d != std::string::npos,
                            ExcMessage(
                              "Scene/Gmsh/Dirichlet tags: '" + item +
                              "' names the component '" + std::string(1, c) +
                              "'; the components of a tag (after ':') are "
                              "letters of '" +
                              letters +
                              "' (e.g. '11: y' fixes u_y on tag 11)."));
                fixed_here[d] = true;
                ++n;
              }
          AssertThrow(n > 0,
                      ExcMessage(
                        "Scene/Gmsh/Dirichlet tags: '" + item +
                        "' names no component after ':' (letters of '" +
                        letters + "', or the tag alone for all)."));
        }
      return fixed;
    }

    template <int dim>
    Tensor<1, dim>
    parse_vector(const std::string &text,
                 const std::string &entry,
                 const double       max_component,
                 const std::string &unit)
    {
      const auto items = Utilities::split_string_list(text, ',');
      AssertThrow(
        items.size() == dim || (dim == 2 && items.size() == 3),
        ExcMessage("Scene/Gmsh/" + entry + " must have " + std::to_string(dim) +
                   " comma-separated components; got '" + text + "'."));
      Tensor<1, dim + 1> v;
      for (unsigned int d = 0; d < items.size(); ++d)
        {
          char *end = nullptr;
          v[d]      = std::strtod(items[d].c_str(), &end);
          AssertThrow(!items[d].empty() && *end == '\0' && std::isfinite(v[d]),
                      ExcMessage("Scene/Gmsh/" + entry +
                                 " must have finite components; got '" + text +
                                 "'."));
          AssertThrow(std::abs(v[d]) <= max_component,
                      ExcMessage("Scene/Gmsh/" + entry +
                                 ": each component must lie in [-" +
                                 format_number(max_component) + ", " +
                                 format_number(max_component) + "] " + unit +
                                 "; got '" + text + "'."));
        }
      // the default has three components; in 2D the third must be zero
      AssertThrow(items.size() == dim || v[dim] == 0.,
                  ExcMessage("Scene/Gmsh/" + entry +
                             " has a third component in 2D (Dimension = 2): "
                             "it must be 0 or left out; got '" +
                             text + "'."));
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        result[d] = v[d];
      return result;
    }

    /// The items of @p text between the @p separator, trimmed, empty ones
    /// kept (Utilities::split_string_list drops a last empty item); none
    /// for an empty text.
    std::vector<std::string>
    split_items(const std::string &text, const char separator)
    {
      std::vector<std::string> items;
      std::string              item;
      for (std::istringstream in(text); std::getline(in, item, separator);)
        items.push_back(Utilities::trim(item));
      if (!text.empty() && text.back() == separator)
        items.emplace_back();
      return items;
    }

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

    /**
     * Checks that @p face_tags (the tags of the boundary faces) has every
     * tag in @p tags, the value of the parameter Scene/Gmsh/@p entry.
     */
    template <typename Tags>
    void
    require_boundary_tags(const std::set<unsigned int> &face_tags,
                          const std::string            &entry,
                          const Tags                   &tags,
                          const std::string            &mesh_file)
    {
      for (const auto tag : tags)
        AssertThrow(face_tags.count(tag),
                    ExcMessage("Scene/Gmsh/" + entry + ": the mesh file '" +
                               mesh_file +
                               "' has no boundary faces with physical tag " +
                               std::to_string(tag) + "."));
    }
  } // namespace



  template <int dim>
  void
  GmshScene<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Gmsh");
    prm.declare_entry("Mesh file",
                      "",
                      Patterns::Anything(),
                      "The .msh file (quadrilaterals in 2D, hexahedra in "
                      "3D); a relative path is relative to the folder of the "
                      "prm file.");
    prm.declare_entry("Body 1 tags",
                      "1",
                      Patterns::Anything(),
                      "Physical tags (comma-separated) of the cells of "
                      "body 1.");
    prm.declare_entry("Body 2 tags",
                      "",
                      Patterns::Anything(),
                      "Physical tags of the cells of body 2; empty for "
                      "a one-body mesh.");
    prm.declare_entry("Dirichlet tags",
                      "",
                      Patterns::Anything(),
                      "Physical tags of boundaries where the displacement "
                      "is held at zero, comma-separated: a tag alone fixes "
                      "all components (a clamp), a tag followed by ':' and "
                      "letters of x, y, z only those (a roller or symmetry "
                      "plane), e.g. '10, 11: y, 12: xz'.");
    prm.declare_entry("Neumann tags",
                      "",
                      Patterns::Anything(),
                      "Physical tags of boundaries loaded by the "
                      "Neumann traction.");
    prm.declare_entry("Neumann traction",
                      "0, 0, 0",
                      Patterns::Anything(),
                      "The traction on the Neumann boundaries, "
                      "components in Pa, each in [-1e15, 1e15] (in 2D a third "
                      "component must be 0).");
    prm.declare_entry("Contact tags of body 1",
                      "",
                      Patterns::Anything(),
                      "Physical tags of the possible contact boundary "
                      "of body 1.");
    prm.declare_entry("Contact tags of body 2",
                      "",
                      Patterns::Anything(),
                      "Physical tags of the possible contact boundary "
                      "of body 2.");
    prm.declare_entry("Initial velocity of body 1",
                      "0, 0, 0",
                      Patterns::Anything(),
                      "Initial velocity of body 1, components in m/s, each in "
                      "[-1e9, 1e9] (in 2D a third component must be 0).");
    prm.declare_entry("Initial velocity of body 2",
                      "0, 0, 0",
                      Patterns::Anything(),
                      "Initial velocity of body 2, components in m/s, each in "
                      "[-1e9, 1e9] (in 2D a third component must be 0).");
    prm.declare_entry("Bodies",
                      "",
                      Patterns::Anything(),
                      "Any number of bodies: the physical tags of the cells "
                      "of each body, comma-separated, the bodies separated "
                      "by ';' (e.g. '1; 2; 3, 4': three bodies, the third of "
                      "tags 3 and 4), instead of Body 1 tags and Body 2 "
                      "tags. Body 1 is of subsection Material, every other "
                      "of Material of body 2. Empty: Body 1 tags and Body 2 "
                      "tags.");
    prm.declare_entry("Contact tags",
                      "",
                      Patterns::Anything(),
                      "With Bodies: the physical tags of each body's "
                      "possible contact boundary, in the order of Bodies, "
                      "separated by ';' (an empty item: none).");
    prm.declare_entry("Initial velocities",
                      "",
                      Patterns::Anything(),
                      "With Bodies: the initial velocity of each body, in "
                      "the order of Bodies, separated by ';', components in "
                      "m/s comma-separated, each in [-1e9, 1e9]; empty: all "
                      "at rest.");
    prm.declare_entry("Contact pairs",
                      "",
                      Patterns::Anything(),
                      "With Bodies: the contact pairs as 'slave : master' "
                      "body numbers, comma-separated (e.g. '2 : 1, 3 : 2'); "
                      "a pair's surfaces are the Contact tags of its bodies, "
                      "its slave's nodes carry the rows (Contact/Slave "
                      "side must then be auto), and a slave node "
                      "that finds a master surface in two pairs keeps the "
                      "row of the nearer. The master can be 'obstacle', the "
                      "rigid obstacle of Obstacle point and Obstacle normal "
                      "(e.g. '1 : obstacle, 2 : 1'; it is one pair for all "
                      "bodies it names, numbered after the pairs of two "
                      "bodies in the statistics). A pair of two bodies can "
                      "have its own search radius in m, in (0, 1e15], "
                      "as a third item (e.g. '2 : 1 : 0.01'), which "
                      "Contact/Search radius does not override.");
    prm.declare_entry("Obstacle point",
                      "",
                      Patterns::Anything(),
                      "With a pair 'slave : obstacle': a point on the "
                      "surface of the rigid obstacle, the half-space behind "
                      "it, components in m, each in [-1e15, 1e15]; empty: "
                      "no obstacle.");
    prm.declare_entry("Obstacle normal",
                      "",
                      Patterns::Anything(),
                      "With a pair 'slave : obstacle': the normal of the "
                      "obstacle's surface, pointing out of the obstacle "
                      "into free space (any length > 0; it is normalised), "
                      "components comma-separated; empty: no obstacle.");
    prm.declare_entry("Gravity",
                      "0, 0, 0",
                      Patterns::Anything(),
                      "Gravitational acceleration g, components in "
                      "m/s^2, each in [-1e15, 1e15] (in 2D a third component "
                      "must be 0); the body force is rho g.");
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  std::vector<std::pair<std::string, std::string>>
  GmshScene<dim>::unread_entries() const
  {
    auto unread = Scene<dim>::unread_entries();
    if (neumann_tags.empty())
      unread.emplace_back("Scene/Gmsh/Neumann traction",
                          "Scene/Gmsh/Neumann tags is empty, so no boundary "
                          "carries the traction");
    if (!pairs_listed && body_tags.size() == 1)
      unread.emplace_back("Scene/Gmsh/Initial velocity of body 2",
                          "the mesh has one body (Scene/Gmsh/Body 2 tags is "
                          "empty)");
    return unread;
  }



  template <int dim>
  void
  GmshScene<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Gmsh");
    mesh_file            = prm.get("Mesh file");
    dirichlet_components = parse_dirichlet_tags<dim>(prm.get("Dirichlet tags"));
    neumann_tags         = parse_tags(prm.get("Neumann tags"), "Neumann tags");
    traction             = parse_vector<dim>(prm.get("Neumann traction"),
                                 "Neumann traction",
                                 1e15,
                                 "Pa");
    gravity = parse_vector<dim>(prm.get("Gravity"), "Gravity", 1e15, "m/s^2");
    const std::string bodies = prm.get("Bodies");
    body_tags.clear();
    contact_tags.clear();
    contact_entries.clear();
    velocity.clear();
    pairs.clear();
    obstacle_slaves.clear();
    pairs_listed = !bodies.empty();
    if (bodies.empty())
      {
        // one or two bodies, one pair
        for (const std::string entry :
             {"Contact tags", "Initial velocities", "Contact pairs"})
          AssertThrow(prm.get(entry).empty(),
                      ExcMessage("Scene/Gmsh/" + entry +
                                 " needs Scene/Gmsh/Bodies (the bodies as a "
                                 "list); with Body 1 tags and Body 2 tags use "
                                 "Contact tags of body 1 and 2 and Initial "
                                 "velocity of body 1 and 2."));
        body_tags.push_back(parse_tags(prm.get("Body 1 tags"), "Body 1 tags"));
        const auto second = parse_tags(prm.get("Body 2 tags"), "Body 2 tags");
        if (!second.empty())
          body_tags.push_back(second);
        for (unsigned int b = 0; b < 2; ++b)
          {
            const std::string entry =
              "Contact tags of body " + std::to_string(b + 1);
            contact_tags.emplace_back();
            for (const auto tag : parse_tags(prm.get(entry), entry))
              contact_tags[b].push_back(tag);
            contact_entries.push_back(entry);
            const std::string v =
              "Initial velocity of body " + std::to_string(b + 1);
            velocity.push_back(parse_vector<dim>(prm.get(v), v, 1e9, "m/s"));
          }
        AssertThrow(!body_tags[0].empty(),
                    ExcMessage(
                      "Scene/Gmsh/Body 1 tags must name at least one tag."));
        for (const auto tag : body_tags[0])
          AssertThrow(second.count(tag) == 0,
                      ExcMessage("Scene/Gmsh: tag " + std::to_string(tag) +
                                 " is in both Body 1 tags and Body 2 tags."));
        AssertThrow(contact_tags[0].empty() == contact_tags[1].empty() &&
                      (contact_tags[0].empty() || body_tags.size() == 2),
                    ExcMessage("Scene/Gmsh: contact needs two bodies, and "
                               "contact tags on both (Contact tags of body 1 "
                               "and 2)."));
        for (const std::string entry : {"Obstacle point", "Obstacle normal"})
          AssertThrow(prm.get(entry).empty(),
                      ExcMessage("Scene/Gmsh/" + entry +
                                 " needs Scene/Gmsh/Bodies and a pair 'body : "
                                 "obstacle' in Scene/Gmsh/Contact pairs."));
        if (!contact_tags[0].empty())
          pairs.push_back({0, 1, 0.});
      }
    else
      {
        // any number of bodies and a list of pairs
        for (const auto &[entry, default_value] :
             std::vector<std::pair<std::string, std::string>>{
               {"Body 1 tags", "1"},
               {"Body 2 tags", ""},
               {"Contact tags of body 1", ""},
               {"Contact tags of body 2", ""},
               {"Initial velocity of body 1", "0, 0, 0"},
               {"Initial velocity of body 2", "0, 0, 0"}})
          AssertThrow(prm.get(entry) == default_value,
                      ExcMessage("Scene/Gmsh/Bodies replaces Body 1 tags, "
                                 "Body 2 tags and their entries; Scene/Gmsh/" +
                                 entry +
                                 " must be left out (use Contact tags and "
                                 "Initial velocities)."));
        for (const std::string &item :
             Utilities::split_string_list(bodies, ';'))
          {
            const auto tags = parse_tags(item, "Bodies");
            AssertThrow(!tags.empty(),
                        ExcMessage("Scene/Gmsh/Bodies = '" + bodies +
                                   "': body " +
                                   std::to_string(body_tags.size() + 1) +
                                   " has no tags."));
            for (const auto tag : tags)
              for (unsigned int b = 0; b < body_tags.size(); ++b)
                AssertThrow(body_tags[b].count(tag) == 0,
                            ExcMessage("Scene/Gmsh/Bodies: tag " +
                                       std::to_string(tag) + " is in body " +
                                       std::to_string(b + 1) + " and in body " +
                                       std::to_string(body_tags.size() + 1) +
                                       "."));
            body_tags.push_back(tags);
          }
        const unsigned int n = body_tags.size();
        AssertThrow(n <= 50,
                    ExcMessage("Scene/Gmsh/Bodies names " + std::to_string(n) +
                               " bodies; at most 50 are supported."));
        const auto per_body = [&](const std::string &entry) {
          const std::string text = prm.get(entry);
          if (text.empty())
            return std::vector<std::string>(n);
          const std::vector<std::string> items = split_items(text, ';');
          AssertThrow(items.size() == n,
                      ExcMessage("Scene/Gmsh/" + entry + " = '" + text +
                                 "' has " + std::to_string(items.size()) +
                                 " items separated by ';'; Scene/Gmsh/Bodies "
                                 "has " +
                                 std::to_string(n) + " bodies."));
          return items;
        };
        const auto contact_items  = per_body("Contact tags");
        const auto velocity_items = per_body("Initial velocities");
        for (unsigned int b = 0; b < n; ++b)
          {
            const std::string entry =
              "Contact tags (body " + std::to_string(b + 1) + ")";
            contact_tags.emplace_back();
            for (const auto tag : parse_tags(contact_items[b], entry))
              contact_tags[b].push_back(tag);
            contact_entries.push_back(entry);
            velocity.push_back(velocity_items[b].empty() ?
                                 Tensor<1, dim>() :
                                 parse_vector<dim>(velocity_items[b],
                                                   "Initial velocities (body " +
                                                     std::to_string(b + 1) +
                                                     ")",
                                                   1e9,
                                                   "m/s"));
          }
        const std::string list = prm.get("Contact pairs");
        for (const std::string &item : Utilities::split_string_list(list, ','))
          {
            const auto sides = split_items(item, ':');
            AssertThrow(sides.size() < 2 || sides[0] != "obstacle",
                        ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                   item +
                                   "' makes the rigid obstacle the slave; it "
                                   "can only be the master (write 'body : "
                                   "obstacle')."));
            std::array<long, 2> body{{0, 0}};
            double              radius = 0.;
            bool                valid  = sides.size() == 2 || sides.size() == 3;
            for (unsigned int k = 0; valid && k < 2; ++k)
              {
                char *end = nullptr;
                body[k]   = std::strtol(sides[k].c_str(), &end, 10);
                valid     = !sides[k].empty() && *end == '\0';
                if (k == 1 && sides[k] == "obstacle")
                  {
                    body[k] = 0;
                    valid   = true;
                  }
              }
            if (valid && sides.size() == 3)
              {
                char *end = nullptr;
                radius    = std::strtod(sides[2].c_str(), &end);
                valid     = !sides[2].empty() && *end == '\0';
              }
            AssertThrow(valid,
                        ExcMessage("Scene/Gmsh/Contact pairs: '" + item +
                                   "' is no pair 'slave : master' of body "
                                   "numbers (the master can be 'obstacle'), "
                                   "or 'slave : master : search radius'."));
            const bool with_obstacle = sides[1] == "obstacle";
            for (unsigned int k = 0; k < (with_obstacle ? 1 : 2); ++k)
              AssertThrow(body[k] >= 1 && body[k] <= long(n),
                          ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                     item + "' names body " + sides[k] +
                                     ", but Scene/Gmsh/Bodies has bodies 1 "
                                     "to " +
                                     std::to_string(n) + "."));
            AssertThrow(body[0] != body[1],
                        ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                   item + "' pairs body " +
                                   std::to_string(body[0]) + " with itself."));
            AssertThrow(sides.size() == 2 || !with_obstacle,
                        ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                   item +
                                   "' gives the rigid obstacle a search "
                                   "radius; every slave node of the obstacle "
                                   "gets a row, leave the radius out."));
            AssertThrow(sides.size() == 2 || (std::isfinite(radius) &&
                                              radius > 0. && radius <= 1e15),
                        ExcMessage("Scene/Gmsh/Contact pairs: the search "
                                   "radius of the pair '" +
                                   item + "' must lie in (0, 1e15] m."));
            const unsigned int slave  = body[0] - 1;
            const unsigned int master = with_obstacle ? 0 : body[1] - 1;
            if (with_obstacle)
              {
                AssertThrow(obstacle_slaves.insert(slave).second,
                            ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                       item + "' is listed twice."));
              }
            else
              {
                for (const BodyPair &pair : pairs)
                  AssertThrow(std::minmax(pair.slave, pair.master) !=
                                std::minmax(slave, master),
                              ExcMessage(
                                "Scene/Gmsh/Contact pairs: the pair '" + item +
                                "' is listed twice (a pair of two "
                                "bodies is listed once, either "
                                "way)."));
              }
            for (unsigned int k = 0; k < (with_obstacle ? 1 : 2); ++k)
              AssertThrow(!contact_tags[body[k] - 1].empty(),
                          ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                     item + "' names body " +
                                     std::to_string(body[k]) +
                                     ", which has no Scene/Gmsh/Contact "
                                     "tags."));
            if (!with_obstacle)
              pairs.push_back({slave, master, radius});
          }
        // the rigid obstacle
        const std::string point  = prm.get("Obstacle point");
        const std::string normal = prm.get("Obstacle normal");
        AssertThrow(!obstacle_slaves.empty() ||
                      (point.empty() && normal.empty()),
                    ExcMessage(
                      "Scene/Gmsh/Obstacle point or Obstacle normal is "
                      "given, but no pair of Scene/Gmsh/Contact pairs "
                      "names the obstacle ('body : obstacle'): name it, "
                      "or leave them out."));
        AssertThrow(obstacle_slaves.empty() ||
                      (!point.empty() && !normal.empty()),
                    ExcMessage(
                      "Scene/Gmsh/Contact pairs names the rigid obstacle: "
                      "give both Scene/Gmsh/Obstacle point and "
                      "Scene/Gmsh/Obstacle normal."));
        if (!obstacle_slaves.empty())
          {
            rigid_obstacle.point =
              Point<dim>(parse_vector<dim>(point, "Obstacle point", 1e15, "m"));
            rigid_obstacle.normal =
              parse_vector<dim>(normal, "Obstacle normal", 1e15, "");
            // (scaled first: the square of a tiny component underflows)
            double largest = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              largest = std::max(largest, std::abs(rigid_obstacle.normal[d]));
            AssertThrow(largest > 0.,
                        ExcMessage("Scene/Gmsh/Obstacle normal = '" + normal +
                                   "' must have a length > 0."));
            // (component by component: Tensor's /= multiplies by the
            // reciprocal, which is infinite for a subnormal largest)
            for (unsigned int d = 0; d < dim; ++d)
              rigid_obstacle.normal[d] = rigid_obstacle.normal[d] / largest;
            const double length = rigid_obstacle.normal.norm();
            for (unsigned int d = 0; d < dim; ++d)
              rigid_obstacle.normal[d] = rigid_obstacle.normal[d] / length;
          }
        // contact tags that no pair uses: bodies that would pass through
        // each other unnoticed
        for (unsigned int b = 0; b < n; ++b)
          if (!contact_tags[b].empty())
            {
              bool paired = obstacle_slaves.count(b) > 0;
              for (const BodyPair &pair : pairs)
                paired = paired || pair.slave == b || pair.master == b;
              AssertThrow(paired,
                          ExcMessage(
                            "Scene/Gmsh/Contact tags give body " +
                            std::to_string(b + 1) +
                            " a contact boundary, but no pair of "
                            "Scene/Gmsh/Contact pairs names it: list its "
                            "pairs (slave : master), or leave its contact "
                            "tags out."));
            }
      }
    prm.leave_subsection();
    prm.leave_subsection();

    AssertThrow(!mesh_file.empty(),
                ExcMessage("Scene/Gmsh/Mesh file must name a .msh file."));
    if (std::filesystem::path(mesh_file).is_relative() &&
        !this->input_directory.empty())
      mesh_file =
        (std::filesystem::path(this->input_directory) / mesh_file).string();
    n_cells       = check_msh_file(mesh_file, dim);
    mesh_checksum = checksum_of_file(mesh_file);
  }



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
    std::set<unsigned int> dirichlet_tags;
    for (const auto &[tag, components] : dirichlet_components)
      dirichlet_tags.insert(tag);
    require_boundary_tags(face_tags,
                          "Dirichlet tags",
                          dirichlet_tags,
                          mesh_file);
    require_boundary_tags(face_tags, "Neumann tags", neumann_tags, mesh_file);
    for (unsigned int b = 0; b < contact_tags.size(); ++b)
      require_boundary_tags(face_tags,
                            contact_entries[b],
                            contact_tags[b],
                            mesh_file);
  }



  template <int dim>
  std::vector<ContactPair>
  GmshScene<dim>::contact_pairs() const
  {
    std::vector<ContactPair> result;
    for (const BodyPair &body_pair : pairs)
      {
        ContactPair pair;
        pair.first_side  = contact_tags[body_pair.slave];
        pair.second_side = contact_tags[body_pair.master];
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
    std::vector<types::boundary_id> ids;
    for (const unsigned int body : obstacle_slaves)
      ids.insert(ids.end(),
                 contact_tags[body].begin(),
                 contact_tags[body].end());
    return ids;
  }



  template <int dim>
  std::optional<RigidObstacle<dim>>
  GmshScene<dim>::obstacle() const
  {
    if (obstacle_slaves.empty())
      return {};
    return rigid_obstacle;
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
    return tractions;
  }



  template <int dim>
  Tensor<1, dim>
  GmshScene<dim>::body_force(const unsigned int body) const
  {
    return this->material(body).density * gravity;
  }



  template <int dim>
  Tensor<1, dim>
  GmshScene<dim>::initial_velocity(const Point<dim>  &x,
                                   const unsigned int body) const
  {
    (void)x;
    return velocity[body];
  }


  DYNCONTACT_REGISTER_SCENE(GmshScene,
                            "gmsh",
                            "any mesh of one or more bodies from a .msh "
                            "file")
} // namespace dyncontact
