#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/checksum.h>
#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/gmsh_scene.h>
#include <dyncontact/scenes/msh_check.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
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

    std::string
    to_list(const std::set<unsigned int> &tags)
    {
      std::string text;
      for (const auto tag : tags)
        text += (text.empty() ? "" : ", ") + std::to_string(tag);
      return text;
    }

    /**
     * The body (0 or 1) whose tags in @p body_tags contain the physical
     * tag @p tag of a cell; throws if neither does.
     */
    unsigned int
    body_of_cell_tag(const unsigned int                           tag,
                     const std::array<std::set<unsigned int>, 2> &body_tags,
                     const std::string                           &mesh_file)
    {
      int body = -1;
      for (unsigned int b = 0; b < 2; ++b)
        if (body_tags[b].count(tag))
          body = b;
      AssertThrow(body >= 0,
                  ExcMessage(
                    "Mesh file '" + mesh_file + "': cells with physical tag " +
                    std::to_string(tag) +
                    " belong to no body (Scene/Gmsh/Body 1 tags = " +
                    to_list(body_tags[0]) + ", Scene/Gmsh/Body 2 tags = " +
                    to_list(body_tags[1]) + ")."));
      return body;
    }

    /**
     * Replaces the physical tag (material id) of every cell of @p tria by
     * the number of its body. Checks that the two bodies share no vertex and
     * that the mesh has cells with every tag in @p body_tags.
     */
    template <int dim>
    void
    set_bodies(Triangulation<dim, dim>                     &tria,
               const std::array<std::set<unsigned int>, 2> &body_tags,
               const std::string                           &mesh_file)
    {
      std::set<unsigned int>               cell_tags;
      std::map<unsigned int, unsigned int> vertex_body;
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int tag = cell->material_id();
          cell_tags.insert(tag);
          const unsigned int body = body_of_cell_tag(tag, body_tags, mesh_file);
          cell->set_material_id(body);
          for (const auto v : cell->vertex_indices())
            {
              const auto [it, inserted] =
                vertex_body.emplace(cell->vertex_index(v), body);
              AssertThrow(inserted || it->second == body,
                          ExcMessage("Mesh file '" + mesh_file +
                                     "': the two bodies share the vertex " +
                                     Utilities::to_string(cell->vertex(v)[0]) +
                                     ", " +
                                     Utilities::to_string(cell->vertex(v)[1]) +
                                     "; bodies in contact must be meshed "
                                     "separately."));
            }
        }
      for (unsigned int b = 0; b < 2; ++b)
        for (const auto tag : body_tags[b])
          AssertThrow(cell_tags.count(tag),
                      ExcMessage("Scene/Gmsh/Body " + std::to_string(b + 1) +
                                 " tags: the mesh file '" + mesh_file +
                                 "' has no cells with physical tag " +
                                 std::to_string(tag) + "."));
    }

    /**
     * The physical tags of the boundary faces of @p tria (whose material
     * ids are bodies, see set_bodies()). Checks that the faces with a tag in
     * @p contact_tags[b] lie on body b.
     */
    template <int dim>
    std::set<unsigned int>
    boundary_tags(
      const Triangulation<dim, dim>                        &tria,
      const std::array<std::vector<types::boundary_id>, 2> &contact_tags,
      const std::string                                    &mesh_file)
    {
      std::set<unsigned int> face_tags;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const unsigned int tag = cell->face(f)->boundary_id();
              face_tags.insert(tag);
              for (unsigned int b = 0; b < 2; ++b)
                AssertThrow(std::find(contact_tags[b].begin(),
                                      contact_tags[b].end(),
                                      tag) == contact_tags[b].end() ||
                              cell->material_id() == b,
                            ExcMessage(
                              "Scene/Gmsh/Contact tags of body " +
                              std::to_string(b + 1) +
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
                      "Physical tags of clamped boundaries (all "
                      "displacement components zero).");
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
  void
  GmshScene<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.enter_subsection("Gmsh");
    mesh_file      = prm.get("Mesh file");
    body_tags[0]   = parse_tags(prm.get("Body 1 tags"), "Body 1 tags");
    body_tags[1]   = parse_tags(prm.get("Body 2 tags"), "Body 2 tags");
    dirichlet_tags = parse_tags(prm.get("Dirichlet tags"), "Dirichlet tags");
    neumann_tags   = parse_tags(prm.get("Neumann tags"), "Neumann tags");
    traction       = parse_vector<dim>(prm.get("Neumann traction"),
                                 "Neumann traction",
                                 1e15,
                                 "Pa");
    for (unsigned int b = 0; b < 2; ++b)
      {
        const std::string entry =
          "Contact tags of body " + std::to_string(b + 1);
        for (const auto tag : parse_tags(prm.get(entry), entry))
          contact_tags[b].push_back(tag);
        const std::string v =
          "Initial velocity of body " + std::to_string(b + 1);
        velocity[b] = parse_vector<dim>(prm.get(v), v, 1e9, "m/s");
      }
    gravity = parse_vector<dim>(prm.get("Gravity"), "Gravity", 1e15, "m/s^2");
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
    AssertThrow(!body_tags[0].empty(),
                ExcMessage(
                  "Scene/Gmsh/Body 1 tags must name at least one tag."));
    for (const auto tag : body_tags[0])
      AssertThrow(body_tags[1].count(tag) == 0,
                  ExcMessage("Scene/Gmsh: tag " + std::to_string(tag) +
                             " is in both Body 1 tags and Body 2 tags."));
    AssertThrow(contact_tags[0].empty() == contact_tags[1].empty() &&
                  (contact_tags[0].empty() || !body_tags[1].empty()),
                ExcMessage("Scene/Gmsh: contact needs two bodies, and "
                           "contact tags on both (Contact tags of body 1 and "
                           "2)."));
  }



  template <int dim>
  void
  GmshScene<dim>::create_coarse_mesh(Triangulation<dim, dim> &tria) const
  {
    std::ifstream in(mesh_file);
    GridIn<dim>   grid_in;
    grid_in.attach_triangulation(tria);
    grid_in.read_msh(in);

    set_bodies(tria, body_tags, mesh_file);
    const auto face_tags = boundary_tags(tria, contact_tags, mesh_file);
    require_boundary_tags(face_tags,
                          "Dirichlet tags",
                          dirichlet_tags,
                          mesh_file);
    require_boundary_tags(face_tags, "Neumann tags", neumann_tags, mesh_file);
    require_boundary_tags(face_tags,
                          "Contact tags of body 1",
                          contact_tags[0],
                          mesh_file);
    require_boundary_tags(face_tags,
                          "Contact tags of body 2",
                          contact_tags[1],
                          mesh_file);
  }



  template <int dim>
  std::vector<ContactPair>
  GmshScene<dim>::contact_pairs() const
  {
    if (contact_tags[0].empty())
      return {};
    ContactPair pair;
    pair.first_side  = contact_tags[0];
    pair.second_side = contact_tags[1];

    return {pair};
  }



  template <int dim>
  std::vector<DirichletBoundary>
  GmshScene<dim>::dirichlet_boundaries() const
  {
    std::vector<DirichletBoundary> boundaries;
    for (const auto tag : dirichlet_tags)
      boundaries.push_back({types::boundary_id(tag)});
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
                            "any one- or two-body mesh from a .msh file")
} // namespace dyncontact
