#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/gmsh_entries.h>
#include <dyncontact/scenes/gmsh_scene.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>


// GmshScene's Manifolds: curved boundary tags that refine onto their
// sphere or cylinder.

namespace dyncontact
{
  using namespace GmshEntries;



  template <int dim>
  void
  GmshScene<dim>::parse_manifolds(ParameterHandler &prm)
  {
    manifolds.clear();
    const std::string text = prm.get("Manifolds");
    const std::string form =
      "' is no 'tag: sphere x, y" + std::string(dim == 3 ? ", z" : "") + "'" +
      (dim == 3 ? " or 'tag: cylinder x, y, z axis a, b, c'" : std::string()) +
      ".";
    for (const std::string &item : split_items(text, ';'))
      {
        if (item.empty())
          continue;
        const std::size_t colon = item.find(':');
        AssertThrow(colon != std::string::npos,
                    ExcMessage("Scene/Gmsh/Manifolds: '" + item + form));
        const auto tags = parse_tags(Utilities::trim(item.substr(0, colon)),
                                     "Manifolds ('" + item + "')");
        AssertThrow(tags.size() == 1,
                    ExcMessage("Scene/Gmsh/Manifolds: '" + item + form));
        std::string       rest  = Utilities::trim(item.substr(colon + 1));
        const std::size_t space = rest.find(' ');
        const std::string kind  = rest.substr(0, space);
        AssertThrow((kind == "sphere" || (dim == 3 && kind == "cylinder")) &&
                      space != std::string::npos,
                    ExcMessage("Scene/Gmsh/Manifolds: '" + item + form +
                               (dim == 2 && kind == "cylinder" ?
                                  " (In 2D a cylinder's section is a circle: "
                                  "'sphere' with its centre.)" :
                                  "")));
        rest = Utilities::trim(rest.substr(space + 1));
        ManifoldBinding binding;
        binding.tag             = *tags.begin();
        binding.cylinder        = kind == "cylinder";
        const std::size_t along = rest.find("axis");
        AssertThrow(binding.cylinder == (along != std::string::npos),
                    ExcMessage("Scene/Gmsh/Manifolds: '" + item + form));
        const std::string entry = "Manifolds ('" + item + "')";
        binding.point           = Point<dim>(parse_vector<dim>(
          Utilities::trim(rest.substr(0, along)), entry, 1e15, "m"));
        if (binding.cylinder)
          {
            binding.axis = parse_vector<dim>(
              Utilities::trim(rest.substr(along + 4)), entry, 1e15, "");
            AssertThrow(binding.axis.norm() > 0.,
                        ExcMessage("Scene/Gmsh/Manifolds: the axis of '" +
                                   item + "' must have a length > 0."));
          }
        for (const ManifoldBinding &other : manifolds)
          AssertThrow(other.tag != binding.tag,
                      ExcMessage("Scene/Gmsh/Manifolds binds tag " +
                                 std::to_string(binding.tag) + " twice."));
        manifolds.push_back(binding);
      }
  }



  template <int dim>
  void
  GmshScene<dim>::attach_manifolds(
    Triangulation<dim, dim>      &tria,
    const std::set<unsigned int> &face_tags) const
  {
    for (const ManifoldBinding &binding : manifolds)
      {
        AssertThrow(face_tags.count(binding.tag),
                    ExcMessage("Scene/Gmsh/Manifolds binds tag " +
                               std::to_string(binding.tag) +
                               ", but the mesh file '" + mesh_file +
                               "' has no boundary faces with that physical "
                               "tag."));
        // the distance of a point from the centre or the axis
        Tensor<1, dim> axis = binding.axis;
        if (binding.cylinder)
          axis /= axis.norm();
        const auto distance = [&](const Point<dim> &x) {
          Tensor<1, dim> d = x - binding.point;
          if (binding.cylinder)
            d -= (d * axis) * axis;
          return d.norm();
        };
        // (the manifold id is the tag; the coarse mesh is on every rank)
        double smallest = std::numeric_limits<double>::max(), largest = 0.;
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == binding.tag)
              {
                for (const unsigned int v : cell->face(f)->vertex_indices())
                  {
                    const double r = distance(cell->face(f)->vertex(v));
                    smallest       = std::min(smallest, r);
                    largest        = std::max(largest, r);
                  }
                cell->face(f)->set_all_manifold_ids(binding.tag);
              }
        AssertThrow(largest - smallest <= 1e-3 * largest && largest > 0.,
                    ExcMessage(
                      "Scene/Gmsh/Manifolds: the vertices of tag " +
                      std::to_string(binding.tag) + " in '" + mesh_file +
                      "' lie between " + format_number(smallest) + " and " +
                      format_number(largest) + " m from the " +
                      (binding.cylinder ? "axis" : "centre") +
                      " (they must agree to 1e-3): the tag is not on this " +
                      (binding.cylinder ? "cylinder" : "sphere") +
                      ". (Surfaces of other radii need tags of their "
                      "own.)"));
        if (binding.cylinder)
          {
            if constexpr (dim == 3)
              tria.set_manifold(binding.tag,
                                CylindricalManifold<dim>(axis, binding.point));
          }
        else
          tria.set_manifold(binding.tag, SphericalManifold<dim>(binding.point));
      }
  }



  // (the class is instantiated where it is registered, in gmsh_scene.cc)
  template void
  GmshScene<2>::parse_manifolds(ParameterHandler &);
  template void
  GmshScene<3>::parse_manifolds(ParameterHandler &);
  template void
  GmshScene<2>::attach_manifolds(Triangulation<2, 2> &,
                                 const std::set<unsigned int> &) const;
  template void
  GmshScene<3>::attach_manifolds(Triangulation<3, 3> &,
                                 const std::set<unsigned int> &) const;
} // namespace dyncontact
