#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/opencascade/manifold_lib.h>
#include <deal.II/opencascade/utilities.h>

#include <dyncontact/base/input_checks.h>
#include <dyncontact/scenes/gmsh_entries.h>
#include <dyncontact/scenes/gmsh_scene.h>

#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <string>


// GmshScene's Manifolds: curved boundary tags that refine onto their
// sphere, cylinder or CAD surface (OpenCASCADE).

namespace dyncontact
{
  using namespace GmshEntries;

  namespace
  {
    /// The extension of @p file in lower case (".step").
    std::string
    lower_case_extension(const std::string &file)
    {
      std::string extension = std::filesystem::path(file).extension();
      for (char &c : extension)
        c = std::tolower(c);
      return extension;
    }



    /// The shape of an IGES or STEP file in m (OpenCASCADE converts the
    /// file's declared length unit to mm, deal.II then by 1e-3 to m), its
    /// lengths times @p scale; refused naming @p entry if it cannot be
    /// read or has no curve (2D) or surface (3D).
    template <int dim>
    TopoDS_Shape
    read_cad_file(const std::string &file,
                  const double       scale,
                  const std::string &entry)
    {
      // (OpenCASCADE reports every file it reads on std::cout, on every
      // rank)
      Message::DefaultMessenger()->RemovePrinters(
        STANDARD_TYPE(Message_PrinterOStream));
      const std::string extension = lower_case_extension(file);
      TopoDS_Shape      shape;
      try
        {
          shape = (extension == ".step" || extension == ".stp") ?
                    OpenCASCADE::read_STEP(file, 1e-3 * scale) :
                    OpenCASCADE::read_IGES(file, 1e-3 * scale);
        }
      catch (const std::exception &)
        {
          shape.Nullify();
        }
      AssertThrow(!shape.IsNull(),
                  ExcMessage("Scene/Gmsh/" + entry +
                             ": OpenCASCADE cannot "
                             "read the CAD file '" +
                             file + "'."));
      const auto [n_faces, n_edges, n_vertices] =
        OpenCASCADE::count_elements(shape);
      (void)n_vertices;
      AssertThrow(dim == 2 ? n_edges > 0 : n_faces > 0,
                  ExcMessage("Scene/Gmsh/" + entry + ": the CAD file '" + file +
                             "' has no " + (dim == 2 ? "curve" : "surface") +
                             "."));
      return shape;
    }
  } // namespace



  template <int dim>
  void
  GmshScene<dim>::parse_manifolds(ParameterHandler &prm)
  {
    manifolds.clear();
    const std::string text = prm.get("Manifolds");
    const std::string form =
      "' is no 'tag: sphere x, y" + std::string(dim == 3 ? ", z" : "") + "'" +
      (dim == 3 ? ", 'tag: cylinder x, y, z axis a, b, c'" : std::string()) +
      " or 'tag: cad file [scale s]'.";
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
        for (const ManifoldBinding &other : manifolds)
          AssertThrow(other.tag != *tags.begin(),
                      ExcMessage("Scene/Gmsh/Manifolds binds tag " +
                                 std::to_string(*tags.begin()) + " twice."));
        if (kind == "cad" && space != std::string::npos)
          {
            // 'cad file [scale s]'
            ManifoldBinding binding;
            binding.tag             = *tags.begin();
            rest                    = Utilities::trim(rest.substr(space + 1));
            const std::size_t scale = rest.find(" scale ");
            binding.cad_file        = Utilities::trim(rest.substr(0, scale));
            const std::string entry = "Manifolds ('" + item + "')";
            if (scale != std::string::npos)
              {
                const std::string text =
                  Utilities::trim(rest.substr(scale + 7));
                char *end         = nullptr;
                binding.cad_scale = std::strtod(text.c_str(), &end);
                AssertThrow(!text.empty() && *end == '\0',
                            ExcMessage("Scene/Gmsh/" + entry + ": the scale '" +
                                       text +
                                       "' is no number (a file name with ' "
                                       "scale ' in it cannot be given)."));
                AssertThrow(std::isfinite(binding.cad_scale) &&
                              binding.cad_scale > 0. &&
                              binding.cad_scale <= 1e15,
                            ExcMessage("Scene/Gmsh/" + entry +
                                       ": the scale must lie in (0, 1e15] "
                                       "(a factor on the lengths of the "
                                       "file in its declared unit)."));
              }
            const std::string extension =
              lower_case_extension(binding.cad_file);
            AssertThrow(extension == ".step" || extension == ".stp" ||
                          extension == ".iges" || extension == ".igs",
                        ExcMessage("Scene/Gmsh/" + entry +
                                   ": the CAD file must be IGES (.iges, .igs) "
                                   "or STEP (.step, .stp)."));
            if (std::filesystem::path(binding.cad_file).is_relative() &&
                !this->input_directory.empty())
              binding.cad_file = (std::filesystem::path(this->input_directory) /
                                  binding.cad_file)
                                   .string();
            AssertThrow(std::filesystem::exists(binding.cad_file),
                        ExcMessage("Scene/Gmsh/" + entry + ": the CAD file '" +
                                   binding.cad_file + "' does not exist."));
            AssertThrow(std::filesystem::is_regular_file(binding.cad_file),
                        ExcMessage("Scene/Gmsh/" + entry + ": the CAD file '" +
                                   binding.cad_file + "' is no regular file."));
            manifolds.push_back(binding);
            continue;
          }
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
        manifolds.push_back(binding);
      }
  }



  template <int dim>
  void
  GmshScene<dim>::attach_manifolds(
    Triangulation<dim, dim>      &tria,
    const std::set<unsigned int> &face_tags) const
  {
    // (3D) edges that faces of two bound tags share: each binding sets the
    // manifold of its faces' edges, so the later binding's wins there
    if (dim == 3 && manifolds.size() > 1)
      {
        std::set<unsigned int> bound;
        for (const ManifoldBinding &binding : manifolds)
          bound.insert(binding.tag);
        std::map<unsigned int, std::set<unsigned int>> tags_of_line;
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                bound.count(cell->face(f)->boundary_id()))
              for (unsigned int l = 0; l < cell->face(f)->n_lines(); ++l)
                tags_of_line[cell->face(f)->line_index(l)].insert(
                  cell->face(f)->boundary_id());
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> shared;
        for (const auto &[line, tags] : tags_of_line)
          if (tags.size() > 1)
            ++shared[{*tags.begin(), *tags.rbegin()}];
        if (Utilities::MPI::this_mpi_process(tria.get_communicator()) == 0)
          for (const auto &[pair, n] : shared)
            {
              unsigned int later = pair.second;
              for (const ManifoldBinding &binding : manifolds)
                if (binding.tag == pair.first || binding.tag == pair.second)
                  later = binding.tag;
              std::cout << "   warning: Scene/Gmsh/Manifolds binds tags "
                        << pair.first << " and " << pair.second
                        << ", whose faces share " << n
                        << " edges: new points on them follow tag " << later
                        << ", the later binding. List the curved surface "
                           "last, or leave a flat one unbound."
                        << std::endl;
            }
      }
    for (const ManifoldBinding &binding : manifolds)
      {
        AssertThrow(face_tags.count(binding.tag),
                    ExcMessage("Scene/Gmsh/Manifolds binds tag " +
                               std::to_string(binding.tag) +
                               ", but the mesh file '" + mesh_file +
                               "' has no boundary faces with that physical "
                               "tag."));
        if (!binding.cad_file.empty())
          {
            attach_cad_surface(tria, binding);
            continue;
          }
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



  template <int dim>
  void
  GmshScene<dim>::attach_cad_surface(Triangulation<dim, dim> &tria,
                                     const ManifoldBinding   &binding) const
  {
    const std::string entry = "Manifolds (tag " + std::to_string(binding.tag) +
                              ": cad " + binding.cad_file + ")";
    const TopoDS_Shape shape =
      read_cad_file<dim>(binding.cad_file, binding.cad_scale, entry);
    const double tolerance =
      std::max(1e-7, OpenCASCADE::get_shape_tolerance(shape));
    // the shape's surfaces (3D) or curves (2D): the tag is bound to those
    // nearest to the centres of its faces, so that a new point near an
    // edge of the shape is not drawn onto a neighbouring surface of the
    // shape that the tag does not cover (a solid's end cap)
    std::vector<TopoDS_Face>   cad_faces;
    std::vector<TopoDS_Edge>   cad_edges;
    std::vector<TopoDS_Vertex> cad_vertices;
    OpenCASCADE::extract_geometrical_shapes(shape,
                                            cad_faces,
                                            cad_edges,
                                            cad_vertices);
    std::vector<TopoDS_Shape> pieces;
    if (dim == 2)
      pieces.assign(cad_edges.begin(), cad_edges.end());
    else
      pieces.assign(cad_faces.begin(), cad_faces.end());
    std::vector<char> used(pieces.size(), 0);
    // the tag's vertices on the surface: within 1e-3 of the size of the
    // tag's faces
    Point<dim> lower, upper;
    bool       first    = true;
    double     farthest = 0.;
    Point<dim> worst;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == binding.tag)
          {
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                const Point<dim> &x = cell->face(f)->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    lower[d] = first ? x[d] : std::min(lower[d], x[d]);
                    upper[d] = first ? x[d] : std::max(upper[d], x[d]);
                  }
                first = false;
                const double distance =
                  x.distance(OpenCASCADE::closest_point(shape, x, tolerance));
                if (distance > farthest)
                  {
                    farthest = distance;
                    worst    = x;
                  }
              }
            cell->face(f)->set_all_manifold_ids(binding.tag);
            // the piece nearest to the face's centre
            const Point<dim> centre  = cell->face(f)->center();
            double           nearest = std::numeric_limits<double>::max();
            unsigned int     which   = 0;
            for (unsigned int k = 0; k < pieces.size(); ++k)
              {
                const double distance = centre.distance(
                  OpenCASCADE::closest_point(pieces[k], centre, tolerance));
                if (distance < nearest)
                  {
                    nearest = distance;
                    which   = k;
                  }
              }
            if (!pieces.empty())
              used[which] = 1;
          }
    const double       size = lower.distance(upper);
    std::ostringstream where;
    where << worst;
    AssertThrow(farthest <= 1e-3 * size,
                ExcMessage(
                  "Scene/Gmsh/" + entry + ": the vertex (" + where.str() +
                  ") of tag " + std::to_string(binding.tag) + " in '" +
                  mesh_file + "' lies " + format_number(farthest) +
                  " m from the CAD " + (dim == 2 ? "curve" : "surface") +
                  " (at most 1e-3 of the tag's size, " + format_number(size) +
                  " m): the tag is not on it (is the scale right?)."));
    BRep_Builder    builder;
    TopoDS_Compound bound;
    builder.MakeCompound(bound);
    for (unsigned int k = 0; k < pieces.size(); ++k)
      if (used[k])
        builder.Add(bound, pieces[k]);
    tria.set_manifold(
      binding.tag,
      OpenCASCADE::NormalProjectionManifold<dim, dim>(bound, tolerance));
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
  template void
  GmshScene<2>::attach_cad_surface(Triangulation<2, 2> &,
                                   const ManifoldBinding &) const;
  template void
  GmshScene<3>::attach_cad_surface(Triangulation<3, 3> &,
                                   const ManifoldBinding &) const;
} // namespace dyncontact
