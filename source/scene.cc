#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/scene.h>
#include <dyncontact/scenes/bar_impact.h>
#include <dyncontact/scenes/gmsh_scene.h>
#include <dyncontact/scenes/hertz.h>
#include <dyncontact/scenes/two_bars.h>

#include <tuple>

namespace dyncontact
{
  void
  declare_scene_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.declare_entry("Name",
                      "bar impact",
                      Patterns::Anything(),
                      "Which scene to run. Available: 'bar impact' (a bar "
                      "against a rigid wall, with an exact solution), 'two "
                      "bars' (two bars meeting head-on, exact), 'hertz' (2D: "
                      "a half-cylinder pressed into or dropping onto a "
                      "block), 'ball on block' (its 3D counterpart), 'gmsh' "
                      "(any one- or two-body mesh from a .msh file).");
    prm.declare_entry("Slave side",
                      "auto",
                      Patterns::Selection("auto|1|2"),
                      "Two-body scenes: which side of the contact pair is the "
                      "slave (its nodes carry the constraint rows): auto (the "
                      "finer side, by mean face size), 1 or 2.");
    prm.declare_entry("Contact search radius",
                      "0",
                      Patterns::Double(0.),
                      "Two-body scenes: slave nodes farther than this from "
                      "the master surface (in the reference configuration) "
                      "get no constraint row, in m; 0 = the scene's default.");
    prm.leave_subsection();
    BarImpact<2>::declare_parameters(prm);
    TwoBars<2>::declare_parameters(prm);
    Hertz<2>::declare_parameters(prm);
    GmshScene<2>::declare_parameters(prm);
  }



  ContactPair
  contact_pair_settings(ParameterHandler &prm)
  {
    ContactPair       pair;
    const std::string slave = prm.get("Slave side");
    pair.slave_side         = (slave == "auto") ? -1 : (slave == "1" ? 0 : 1);
    pair.search_radius      = prm.get_double("Contact search radius");
    return pair;
  }



  template <int dim>
  std::unique_ptr<Scene<dim>>
  create_scene(ParameterHandler            &prm,
               const std::vector<Material> &materials,
               const std::string           &input_directory)
  {
    prm.enter_subsection("Scene");
    const std::string name = prm.get("Name");
    prm.leave_subsection();

    if (name == "bar impact")
      return std::make_unique<BarImpact<dim>>(prm, materials[0]);
    if (name == "two bars")
      return std::make_unique<TwoBars<dim>>(prm, materials[0]);
    if (name == "hertz")
      {
        AssertThrow(dim == 2,
                    ExcMessage("Scene 'hertz' is two-dimensional (set "
                               "Dimension = 2); its 3D counterpart is 'ball "
                               "on block'."));
        return std::make_unique<Hertz<dim>>(prm, materials, name);
      }
    if (name == "ball on block")
      {
        AssertThrow(dim == 3,
                    ExcMessage("Scene 'ball on block' is three-dimensional "
                               "(set Dimension = 3); its 2D counterpart is "
                               "'hertz'."));
        return std::make_unique<Hertz<dim>>(prm, materials, name);
      }

    if (name == "gmsh")
      return std::make_unique<GmshScene<dim>>(prm, materials, input_directory);

    AssertThrow(false,
                ExcMessage("Scene/Name must be one of: 'bar impact', 'two "
                           "bars', 'hertz', 'ball on block', 'gmsh'; got '" +
                           name + "'."));
    return nullptr;
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
    result.create_triangulation(vertices, cells, subcell_data);
  }

  template std::unique_ptr<Scene<2>>
  create_scene<2>(ParameterHandler &,
                  const std::vector<Material> &,
                  const std::string &);
  template std::unique_ptr<Scene<3>>
  create_scene<3>(ParameterHandler &,
                  const std::vector<Material> &,
                  const std::string &);
  template void
  merge_bodies<2>(const std::vector<const Triangulation<2, 2> *> &,
                  Triangulation<2, 2> &);
  template void
  merge_bodies<3>(const std::vector<const Triangulation<3, 3> *> &,
                  Triangulation<3, 3> &);
} // namespace dyncontact
