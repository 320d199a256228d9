#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/checksum.h>
#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/body_overlap.h>
#include <dyncontact/scenes/gmsh_entries.h>
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


// GmshScene's parameters: their declaration and reading, by job (the mesh
// and the scene's queries are in gmsh_scene.cc).

namespace dyncontact
{
  using namespace GmshEntries;



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
    prm.declare_entry("Neumann tractions",
                      "",
                      Patterns::Anything(),
                      "A traction of its own per boundary tag, items "
                      "separated by ';': 'tag: components in Pa', e.g. "
                      "'13: 0, -2; 14: 1, 0' (each component in [-1e15, "
                      "1e15]), or functions of x, y (, z) and t in s "
                      "(muparser syntax, constants of Function constants), "
                      "e.g. '13: 0, -2*min(t/0.1, 1)'; a tag here must not "
                      "be in Neumann tags.");
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
                      "of Material of body 2, unless the entries of "
                      "Material are lists of one value per body. Empty: "
                      "Body 1 tags and Body 2 tags.");
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
                      "or those of them it names in parentheses after the "
                      "body (e.g. '2 (12) : 1 (11), 2 (14 15) : 3': a body "
                      "can meet different bodies with different surfaces; "
                      "every contact tag must be in a pair), "
                      "its slave's nodes carry the rows (Contact/Slave "
                      "side must then be auto), and a slave node "
                      "that finds a master surface in two pairs keeps the "
                      "row of the nearer. The master can be 'obstacle', the "
                      "rigid obstacle of Obstacle point and Obstacle normal "
                      "(e.g. '1 : obstacle, 2 : 1'), or 'obstacle k', the "
                      "k-th of Obstacles; an obstacle is one pair for all "
                      "bodies it names, numbered after the pairs of two "
                      "bodies in the statistics. A pair of two bodies can "
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
    prm.declare_entry(
      "Obstacles",
      "",
      Patterns::Anything(),
      "Rigid obstacles, instead of Obstacle point and Obstacle normal, items "
      "separated by ';', the k-th named 'obstacle k' in Contact pairs: "
      "'plane x, y[, z] normal a, b[, c]' (the half-space behind the point, "
      "m, with the outward normal), 'sphere x, y[, z] radius r' (a ball, in "
      "2D a disc: centre and radius, m) or 'cylinder x, y, z axis a, b, c "
      "radius r' (3D: a solid cylinder about the axis through the point), "
      "e.g. 'plane 0, 0 normal 1, 1; plane 0, 0 normal -1, 1' (a "
      "V-groove). An item may end with 'moving d1, d2[, d3]': a prescribed "
      "translation d(t) of the obstacle (m; expressions in t and the "
      "Function constants, not in x, y, z), e.g. 'plane 0, 0.5 normal 0, -1 "
      "moving 0, -0.1*t' (a rigid punch pressed down at 0.1 m/s). A slave "
      "node gets the constraint of the obstacle's surface nearest to it at "
      "t = 0 (at d(0)), linearised there; a moving obstacle's gap is that "
      "gap plus nu . (d(t) - d(0)).");
    prm.declare_entry(
      "Initial displacement",
      "",
      Patterns::Anything(),
      "The initial displacement as a function of x, y (and z in 3D), in m: "
      "its components separated by ';' (deal.II's function parser, "
      "muparser syntax), with the constant 'body' (the body's number, 1, 2, "
      "...) and those of Function constants, e.g. '0.01*x; 0' or "
      "'0; if(body == 2, -0.001*y, 0)'. Empty: zero.");
    prm.declare_entry(
      "Initial velocity",
      "",
      Patterns::Anything(),
      "The initial velocity as a function of x, y (and z in 3D), in m/s, "
      "as Initial displacement (e.g. a body spinning about (0, 0.5): "
      "'-omega*(y - 0.5); omega*x' with Function constants 'omega = 2'), "
      "instead of Initial velocity of body 1 and 2 or Initial velocities. "
      "Empty: those.");
    prm.declare_entry("Function constants",
                      "",
                      Patterns::Anything(),
                      "Named constants of the functions (Initial "
                      "displacement, Initial velocity, Body force, "
                      "Pressures, Neumann tractions, Prescribed "
                      "displacements), comma-separated 'name = value' "
                      "(e.g. 'omega = 2, R = 0.5').");
    prm.declare_entry(
      "Body force",
      "",
      Patterns::Anything(),
      "A body force density in N/m^3 (in 2D per unit thickness) as a "
      "function of x, y (, z) and t in s, its components separated by ';' "
      "(muparser syntax, with the constant 'body' and those of Function "
      "constants), added to rho g of Gravity, e.g. '0; -1e4*min(t/0.1, 1)'. "
      "A function of t is evaluated at every step's end, one of x only once "
      "per mesh. Empty: none.");
    prm.declare_entry(
      "Prescribed displacements",
      "",
      Patterns::Anything(),
      "Displacements that move, per tag of Dirichlet tags, in m, as "
      "functions of x, y (, z) and t in s, items separated by ';': 'tag: "
      "components' (muparser syntax, constants of Function constants), "
      "e.g. '11: 0, -0.01*(1 - cos(pi*min(t/0.2, 1)))/2'. Only the "
      "components the tag fixes move (the others must be 0). A node shared "
      "with a tag that holds zero stays at zero. Needs Time "
      "integration/Mass matrix = lumped.");
    prm.declare_entry(
      "Pressures",
      "",
      Patterns::Anything(),
      "A normal pressure per boundary tag in Pa, positive pushing into the "
      "body (the traction -p n), as a function of x, y (, z) and t in s, "
      "items separated by ';': 'tag: expression', e.g. '11: 1e5*min(t/0.2, "
      "1); 12: 2e4'. A tag has at most one load (Neumann tags, Neumann "
      "tractions, Pressures).");
    prm.declare_entry(
      "Manifolds",
      "",
      Patterns::Anything(),
      "Curved boundaries: boundary tags bound to a sphere (in 2D a circle) "
      "or a cylinder (3D), so that every refinement, the initial ones and "
      "those of an adaptive mesh, puts the new boundary points on the "
      "surface, items separated by ';': 'tag: sphere x, y[, z]' (the "
      "centre, m) or 'tag: cylinder x, y, z axis a, b, c' (a point on the "
      "axis, m, and its direction), or 'tag: cad file [scale s]' (the "
      "surface, in 2D the curve, of an IGES or STEP file through "
      "OpenCASCADE, read in m from the file's declared length unit, its "
      "lengths then times s, default 1, e.g. 1000 for numbers in m that the "
      "file declares as mm; a relative file name is relative to the prm "
      "file), e.g. "
      "'20: sphere 0, 0.5; 21: cad part.step'. All vertices of a sphere's "
      "or a cylinder's tag must lie at one distance from the centre or the "
      "axis, those of a CAD tag on its surface.");
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
    bool moving_obstacle = false;
    for (const auto &obstacle : rigid_obstacles)
      moving_obstacle = moving_obstacle || obstacle.motion != nullptr;
    if (displacement_functions.empty() && velocity_functions.empty() &&
        traction_functions.empty() && pressure_functions.empty() &&
        body_force_functions.empty() && prescribed_functions.empty() &&
        !moving_obstacle)
      unread.emplace_back("Scene/Gmsh/Function constants",
                          "no function uses them (Initial displacement, "
                          "Initial velocity, Body force, Pressures, "
                          "Prescribed displacements, a traction of Neumann "
                          "tractions that is no number or an obstacle's "
                          "motion in Obstacles)");
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
    parse_manifolds(prm);
    const std::string bodies = prm.get("Bodies");
    body_tags.clear();
    contact_tags.clear();
    contact_entries.clear();
    velocity.clear();
    pairs.clear();
    obstacle_slaves.clear();
    obstacle_tags.clear();
    rigid_obstacles.clear();
    unnumbered_obstacle = false;
    pairs_listed        = !bodies.empty();
    if (bodies.empty())
      parse_two_bodies(prm);
    else
      {
        parse_body_list(prm, bodies);
        parse_contact_pairs(prm);
        parse_obstacle(prm);
        refuse_unpaired_contact_tags();
      }
    parse_loads(prm);
    parse_initial_functions(prm);
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
  GmshScene<dim>::parse_two_bodies(ParameterHandler &prm)
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
    for (const std::string entry :
         {"Obstacle point", "Obstacle normal", "Obstacles"})
      AssertThrow(prm.get(entry).empty(),
                  ExcMessage("Scene/Gmsh/" + entry +
                             " needs Scene/Gmsh/Bodies and a pair 'body : "
                             "obstacle' in Scene/Gmsh/Contact pairs."));
    if (!contact_tags[0].empty())
      pairs.push_back({0, 1, 0., contact_tags[0], contact_tags[1]});
  }



  template <int dim>
  void
  GmshScene<dim>::parse_body_list(ParameterHandler  &prm,
                                  const std::string &bodies)
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
    for (const std::string &item : Utilities::split_string_list(bodies, ';'))
      {
        const auto tags = parse_tags(item, "Bodies");
        AssertThrow(!tags.empty(),
                    ExcMessage("Scene/Gmsh/Bodies = '" + bodies + "': body " +
                               std::to_string(body_tags.size() + 1) +
                               " has no tags."));
        for (const auto tag : tags)
          for (unsigned int b = 0; b < body_tags.size(); ++b)
            AssertThrow(body_tags[b].count(tag) == 0,
                        ExcMessage("Scene/Gmsh/Bodies: tag " +
                                   std::to_string(tag) + " is in body " +
                                   std::to_string(b + 1) + " and in body " +
                                   std::to_string(body_tags.size() + 1) + "."));
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
                  ExcMessage("Scene/Gmsh/" + entry + " = '" + text + "' has " +
                             std::to_string(items.size()) +
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
                                                 std::to_string(b + 1) + ")",
                                               1e9,
                                               "m/s"));
      }
  }



  template <int dim>
  void
  GmshScene<dim>::refuse_unpaired_contact_tags() const
  {
    const unsigned int n = body_tags.size();
    // contact tags that no pair uses: surfaces that would pass through
    // others unnoticed
    for (unsigned int b = 0; b < n; ++b)
      for (const auto tag : contact_tags[b])
        {
          bool paired = false;
          for (unsigned int k = 0; k < obstacle_slaves.size(); ++k)
            paired = paired || (obstacle_slaves[k].count(b) > 0 &&
                                obstacle_tags[k].count(tag));
          for (const BodyPair &pair : pairs)
            for (const auto &[body, tags] :
                 {std::make_pair(pair.slave, &pair.slave_tags),
                  std::make_pair(pair.master, &pair.master_tags)})
              paired = paired || (body == b &&
                                  std::find(tags->begin(), tags->end(), tag) !=
                                    tags->end());
          AssertThrow(paired,
                      ExcMessage("Scene/Gmsh/Contact tags give body " +
                                 std::to_string(b + 1) +
                                 " a contact boundary (tag " +
                                 std::to_string(tag) +
                                 "), but no pair of Scene/Gmsh/Contact pairs "
                                 "names it: list its pairs (slave : master), "
                                 "or leave its contact tags out."));
        }
  }



  // (the class is instantiated where it is registered, in gmsh_scene.cc)
#define DYNCONTACT_INSTANTIATE(dim)                                     \
  template void GmshScene<dim>::declare_parameters(ParameterHandler &); \
  template std::vector<std::pair<std::string, std::string>>             \
                GmshScene<dim>::unread_entries() const;                 \
  template void GmshScene<dim>::parse_parameters(ParameterHandler &);   \
  template void GmshScene<dim>::parse_two_bodies(ParameterHandler &);   \
  template void GmshScene<dim>::parse_body_list(ParameterHandler &,     \
                                                const std::string &);   \
  template void GmshScene<dim>::refuse_unpaired_contact_tags() const;
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
