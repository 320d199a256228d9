#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/memory_check.h>
#include <dyncontact/scenes/interface.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace dyncontact
{
  template class PluginRegistry<Scene>;



  template <int dim>
  std::vector<std::string>
  Scene<dim>::material_subsections() const
  {
    // body 1 "Material", every other "Material of body 2"
    std::vector<std::string> subsections(n_bodies(), "Material of body 2");
    subsections[0] = "Material";
    return subsections;
  }



  template <int dim>
  std::vector<types::boundary_id>
  Scene<dim>::all_contact_boundary_ids() const
  {
    std::vector<types::boundary_id> ids = contact_boundary_ids();
    for (const auto &obstacle : obstacles())
      ids.insert(ids.end(),
                 obstacle.boundary_ids.begin(),
                 obstacle.boundary_ids.end());
    for (const auto &pair : contact_pairs())
      {
        ids.insert(ids.end(), pair.first_side.begin(), pair.first_side.end());
        ids.insert(ids.end(), pair.second_side.begin(), pair.second_side.end());
      }
    return ids;
  }



  template <int dim>
  bool
  Scene<dim>::has_contact() const
  {
    return !obstacles().empty() || !contact_pairs().empty();
  }



  template <int dim>
  bool
  Scene<dim>::one_material() const
  {
    return std::all_of(materials.begin(),
                       materials.end(),
                       [&](const Material &m) { return m == materials[0]; });
  }



  template <int dim>
  bool
  Scene<dim>::is_viscous() const
  {
    bool viscous = false;
    for (unsigned int b = 0; b < n_bodies(); ++b)
      viscous = viscous || material(b).is_viscous();
    return viscous;
  }



  template <int dim>
  std::vector<std::pair<std::string, std::string>>
  Scene<dim>::unread_entries() const
  {
    if (materials_per_body)
      return {{"Material of body 2",
               "the lists in subsection Material give each body its "
               "material"}};
    const auto subsections = material_subsections();
    if (std::find(subsections.begin(),
                  subsections.end(),
                  "Material of body 2") != subsections.end())
      return {};
    return {{"Material of body 2",
             "the '" + name() + "' scene makes " +
               (n_bodies() == 1 ?
                  std::string("its one body") :
                  "each of its " + std::to_string(n_bodies()) + " bodies") +
               " of Material"}};
  }



  template <int dim>
  std::string
  Scene<dim>::subsection() const
  {
    std::string name = scene_name;
    if (!name.empty())
      name[0] = std::toupper(name[0]);
    return "Scene/" + name;
  }



  void
  declare_scene_parameters(ParameterHandler &prm)
  {
    std::string list;
    for (const auto &info : PluginRegistry<Scene>::plugins())
      list += "'" + info.name + "' (" + info.description + "); ";
    prm.enter_subsection("Scene");
    prm.declare_entry("Name",
                      "bar impact",
                      Patterns::Anything(),
                      "Which scene to run. Each scene reads its own "
                      "subsection Scene/<Name> (e.g. Scene/Bar impact). "
                      "Available: " +
                        list.substr(0, list.size() - 2) + ".");
    prm.leave_subsection();
    PluginRegistry<Scene>::declare_parameters(prm);
  }



  template <int dim>
  std::unique_ptr<Scene<dim>>
  create_scene(ParameterHandler  &prm,
               const std::string &input_directory,
               const unsigned int polynomial_degree,
               const bool         stored_step_matrix)
  {
    prm.enter_subsection("Scene");
    const std::string name = prm.get("Name");
    prm.leave_subsection();

    const auto *info = PluginRegistry<Scene>::find(name);
    AssertThrow(info != nullptr,
                ExcMessage("Scene/Name must be one of: '" +
                           PluginRegistry<Scene>::names("', '") + "'; got '" +
                           name + "'."));
    std::unique_ptr<Scene<dim>> scene = info->template create<dim>();
    scene->scene_name                 = name;
    scene->input_directory            = input_directory;
    scene->polynomial_degree          = polynomial_degree;
    scene->stored_step_matrix         = stored_step_matrix;
    scene->parse_parameters(prm);
    // lists in Material give each body its own; else each body reads the
    // subsection the scene names
    scene->materials =
      Material::parse_per_body(prm, scene->n_bodies(), "Material");
    scene->materials_per_body = !scene->materials.empty();
    if (!scene->materials_per_body)
      for (const std::string &subsection : scene->material_subsections())
        {
          Material material;
          material.parse_parameters(prm, subsection);
          scene->materials.push_back(material);
        }
    return scene;
  }



  template <int dim>
  void
  merge_bodies(const std::vector<const Triangulation<dim, dim> *> &bodies,
               Triangulation<dim, dim>                            &result)
  {
    std::vector<Point<dim>>    vertices;
    std::vector<CellData<dim>> cells;
    SubCellData                subcell_data;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const auto [body_vertices, body_cells, body_subcells] =
          GridTools::get_coarse_mesh_description(*bodies[b]);
        const unsigned int offset = vertices.size();
        vertices.insert(vertices.end(),
                        body_vertices.begin(),
                        body_vertices.end());
        for (CellData<dim> cell : body_cells)
          {
            for (auto &v : cell.vertices)
              v += offset;
            cell.material_id = b;
            cells.push_back(cell);
          }
        for (CellData<1> line : body_subcells.boundary_lines)
          {
            for (auto &v : line.vertices)
              v += offset;
            subcell_data.boundary_lines.push_back(line);
          }
        for (CellData<2> quad : body_subcells.boundary_quads)
          {
            for (auto &v : quad.vertices)
              v += offset;
            subcell_data.boundary_quads.push_back(quad);
          }
      }
    // deal.II 9.4 and p4est disagree on refinement across rotated or
    // flipped faces (the 3D quarter ball has them): order the cells so that
    // faces are in standard orientation where possible
    if (dim == 3)
      GridTools::consistently_order_cells(cells);
    result.create_triangulation(vertices, cells, subcell_data);
  }

  template <int dim>
  void
  build_mesh(const Scene<dim>        &scene,
             Triangulation<dim, dim> &triangulation,
             const unsigned int       global_refinements,
             const unsigned int       degree,
             const bool               coarse_only)
  {
    const MPI_Comm    comm   = triangulation.get_communicator();
    const std::string remedy = "Mesh/Initial global refinements (now " +
                               std::to_string(global_refinements) +
                               ") or the cell counts in " + scene.subsection();
    const double coarse = scene.n_coarse_cells();
    check_mesh_fits_in_memory(coarse * std::pow(2., dim * global_refinements),
                              dim,
                              degree,
                              scene.stores_step_matrix(),
                              coarse,
                              remedy,
                              comm);
    scene.create_coarse_mesh(triangulation);
    if (!coarse_only)
      {
        for (unsigned int k = 0; k < global_refinements; ++k)
          {
            check_mesh_fits_in_memory(triangulation.n_global_active_cells() *
                                        std::pow(2., dim),
                                      dim,
                                      degree,
                                      scene.stores_step_matrix(),
                                      triangulation.n_cells(0),
                                      remedy,
                                      comm);
            triangulation.refine_global(1);
          }
        scene.refine_initial_mesh(triangulation);
      }
    for (const auto &cell : triangulation.active_cell_iterators())
      AssertThrow(cell->material_id() < scene.n_bodies(),
                  ExcMessage("A cell of the mesh has material id " +
                             std::to_string(cell->material_id()) +
                             ", but the scene has " +
                             std::to_string(scene.n_bodies()) +
                             " bodies (ids 0 to n-1)."));
  }

  template <int dim>
  std::vector<std::set<types::boundary_id>>
  boundary_ids_of_bodies(const Triangulation<dim, dim> &triangulation,
                         const unsigned int             n_bodies)
  {
    // (id, body) as one key id * n_bodies + body, for the union over all
    // ranks
    std::set<unsigned long long> keys;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            keys.insert(
              static_cast<unsigned long long>(cell->face(f)->boundary_id()) *
                n_bodies +
              cell->material_id());
    std::vector<std::set<types::boundary_id>> ids(n_bodies);
    for (const unsigned long long key :
         Utilities::MPI::compute_set_union(keys,
                                           triangulation.get_communicator()))
      ids[key % n_bodies].insert(key / n_bodies);
    return ids;
  }



  template class Scene<2>;
  template class Scene<3>;
  template std::vector<std::set<types::boundary_id>>
  boundary_ids_of_bodies<2>(const Triangulation<2, 2> &, const unsigned int);
  template std::vector<std::set<types::boundary_id>>
  boundary_ids_of_bodies<3>(const Triangulation<3, 3> &, const unsigned int);
  template void
  build_mesh<2>(const Scene<2> &,
                Triangulation<2, 2> &,
                const unsigned int,
                const unsigned int,
                const bool);
  template void
  build_mesh<3>(const Scene<3> &,
                Triangulation<3, 3> &,
                const unsigned int,
                const unsigned int,
                const bool);
  template std::unique_ptr<Scene<2>>
  create_scene<2>(ParameterHandler &,
                  const std::string &,
                  const unsigned int,
                  const bool);
  template std::unique_ptr<Scene<3>>
  create_scene<3>(ParameterHandler &,
                  const std::string &,
                  const unsigned int,
                  const bool);
  template void
  merge_bodies<2>(const std::vector<const Triangulation<2, 2> *> &,
                  Triangulation<2, 2> &);
  template void
  merge_bodies<3>(const std::vector<const Triangulation<3, 3> *> &,
                  Triangulation<3, 3> &);
} // namespace dyncontact
