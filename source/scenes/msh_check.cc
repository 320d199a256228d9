// The check of a Gmsh .msh file before deal.II's GridIn reads it.

#include <deal.II/base/exceptions.h>

#include <dyncontact/scenes/msh_check.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_set>
#include <vector>

namespace dyncontact
{
  using namespace dealii;

  std::size_t
  check_msh_file(const std::string &name, const int dim)
  {
    const std::string file = "Scene/Gmsh/Mesh file '" + name + "'";
    AssertThrow(std::filesystem::exists(name),
                ExcMessage(file + " does not exist."));
    AssertThrow(std::filesystem::is_regular_file(name),
                ExcMessage(file + " is not a regular file."));
    std::ifstream in(name);
    AssertThrow(in.good(), ExcMessage(file + " cannot be opened."));
    AssertThrow(std::filesystem::file_size(name) > 0,
                ExcMessage(file + " is empty."));

    std::size_t line_number = 0;
    std::string line;
    auto        next = [&](const std::string &what) -> std::istringstream {
      AssertThrow(std::getline(in, line),
                  ExcMessage(file + " ends at line " +
                             std::to_string(line_number) + " while " + what +
                             " were expected: the file is truncated."));
      ++line_number;
      if (!line.empty() && line.back() == '\r')
        line.pop_back();
      return std::istringstream(line);
    };
    auto fail = [&](const std::string &what) {
      AssertThrow(false,
                  ExcMessage(file + ", line " + std::to_string(line_number) +
                             ": " + what + " (the line reads '" +
                             line.substr(0, 80) + "')."));
    };
    auto read_count = [&](std::istringstream &s, const std::string &what) {
      long long n = -1;
      s >> n;
      if (s.fail() || n < 0)
        fail("expected the number of " + what);
      return std::size_t(n);
    };
    // nodes per element of the Gmsh element types
    const std::map<int, unsigned int> nodes_per_element = {{1, 2},
                                                           {2, 3},
                                                           {3, 4},
                                                           {4, 4},
                                                           {5, 8},
                                                           {6, 6},
                                                           {7, 5},
                                                           {8, 3},
                                                           {9, 6},
                                                           {10, 9},
                                                           {11, 10},
                                                           {12, 27},
                                                           {15, 1},
                                                           {16, 8},
                                                           {17, 20}};
    auto                              check_type        = [&](const int type) {
      if (type == 15 || type == 1 || type == 3 || (dim == 3 && type == 5))
        return;
      if (type == 2 || type == 4 || type == 6 || type == 7)
        fail(
          std::string("the mesh has ") +
          (type == 2 ? "triangles" :
                                               type == 4 ? "tetrahedra" :
                                               type == 6 ? "prisms" :
                                                           "pyramids") +
          ", but only quadrilaterals (2D) and hexahedra (3D) are "
                                              "supported. Let Gmsh recombine the mesh: 'Mesh.RecombineAll = "
                                              "1;' (2D), plus 'Mesh.Recombine3DAll = 1;' or transfinite "
                                              "volumes with 'Recombine Volume' (3D), or 'Mesh.SubdivisionAlgorithm "
                                              "= 1;' (2D) / '= 2;' (3D) to split every element into "
                                              "quadrilaterals/hexahedra");
      fail("element type " + std::to_string(type) +
           " is not supported: only first-order points, lines, "
                                               "quadrilaterals and (3D) hexahedra");
    };

    int                           version = 0;
    bool                          nodes = false, elements = false;
    std::size_t                   n_cells = 0;
    std::unordered_set<long long> node_ids;
    while (std::getline(in, line))
      {
        ++line_number;
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        if (line == "$MeshFormat")
          {
            auto   s      = next("the format");
            double format = 0.;
            int    binary = -1;
            s >> format >> binary;
            if (s.fail())
              fail("expected 'version file-type data-size'");
            if (binary != 0)
              fail("binary .msh files are not supported; save the mesh "
                   "as ASCII (gmsh -save -format msh2 or msh4)");
            version = int(format);
            if (version != 2 && version != 4)
              fail("the .msh format " + std::to_string(format) +
                   " is not supported (2.2 and 4.1 are)");
          }
        else if (line == "$Nodes")
          {
            if (version == 0)
              fail("$Nodes before $MeshFormat: this is no .msh file");
            auto        s      = next("the node counts");
            std::size_t blocks = 1, n = 0;
            if (version == 4)
              blocks = read_count(s, "node blocks");
            n = read_count(s, "nodes");
            if (std::min<std::size_t>(n, 1u << 20) >
                std::filesystem::file_size(name))
              fail("more nodes than the file could hold");
            std::size_t read = 0;
            for (std::size_t b = 0; b < blocks; ++b)
              {
                std::size_t            in_block = n;
                std::vector<long long> tags;
                if (version == 4)
                  {
                    auto sb = next("a node block header");
                    int  entity_dim, entity_tag, parametric;
                    sb >> entity_dim >> entity_tag >> parametric;
                    in_block = read_count(sb, "nodes in the block");
                    if (parametric != 0)
                      fail("parametric nodes are not supported");
                    for (std::size_t k = 0; k < in_block; ++k)
                      {
                        auto      st  = next("node tags");
                        long long tag = -1;
                        st >> tag;
                        if (st.fail())
                          fail("expected a node tag");
                        tags.push_back(tag);
                      }
                  }
                for (std::size_t k = 0; k < in_block; ++k)
                  {
                    auto      sn = next("nodes");
                    long long id = 0;
                    if (version == 2)
                      sn >> id;
                    else
                      id = tags[k];
                    std::string x[3];
                    sn >> x[0] >> x[1] >> x[2];
                    if (sn.fail())
                      fail("expected a node with three coordinates");
                    for (const auto &c : x)
                      {
                        char  *end   = nullptr;
                        double value = std::strtod(c.c_str(), &end);
                        if (*end != '\0' || !std::isfinite(value))
                          fail("the coordinate '" + c +
                               "' is not a finite number");
                      }
                    node_ids.insert(id);
                    ++read;
                  }
              }
            if (read != n)
              fail("the node blocks hold " + std::to_string(read) +
                   " nodes, the header says " + std::to_string(n));
            if (next("$EndNodes").str() != "$EndNodes")
              fail("expected $EndNodes");
            nodes = true;
          }
        else if (line == "$Elements")
          {
            if (!nodes)
              fail("$Elements before $Nodes");
            auto        s      = next("the element counts");
            std::size_t blocks = 1, n = 0;
            if (version == 4)
              blocks = read_count(s, "element blocks");
            n = read_count(s, "elements");
            for (std::size_t b = 0; b < blocks; ++b)
              {
                std::size_t in_block = n;
                int         type     = 0;
                if (version == 4)
                  {
                    auto sb = next("an element block header");
                    int  entity_dim, entity_tag;
                    sb >> entity_dim >> entity_tag >> type;
                    in_block = read_count(sb, "elements in the block");
                    check_type(type);
                  }
                for (std::size_t k = 0; k < in_block; ++k)
                  {
                    auto      se = next("elements");
                    long long id = 0;
                    se >> id;
                    if (version == 2)
                      {
                        int n_tags = 0;
                        se >> type >> n_tags;
                        if (se.fail() || n_tags < 0)
                          fail("expected 'id type number-of-tags ...'");
                        check_type(type);
                        for (int t = 0; t < n_tags; ++t)
                          se >> id;
                      }
                    const auto nodes_of = nodes_per_element.find(type);
                    for (unsigned int v = 0; v < nodes_of->second; ++v)
                      {
                        long long node = 0;
                        se >> node;
                        if (se.fail())
                          fail("expected " + std::to_string(nodes_of->second) +
                               " node tags of the element");
                        if (node_ids.count(node) == 0)
                          fail("the element refers to node " +
                               std::to_string(node) +
                               ", which $Nodes does not define");
                      }
                    if (type == (dim == 2 ? 3 : 5))
                      ++n_cells;
                  }
              }
            if (next("$EndElements").str() != "$EndElements")
              fail("expected $EndElements");
            elements = true;
          }
      }
    AssertThrow(version != 0,
                ExcMessage(file + " has no $MeshFormat section: it is no "
                                  "Gmsh .msh file."));
    AssertThrow(nodes && elements,
                ExcMessage(file + " has no " +
                           (nodes ? "$Elements" : "$Nodes") +
                           " section: the file is truncated."));
    AssertThrow(n_cells > 0,
                ExcMessage(file + " has no " +
                           (dim == 2 ? "quadrilaterals" : "hexahedra") +
                           ": is it a mesh for the other dimension (set "
                           "Dimension)?"));
    return n_cells;
  }
} // namespace dyncontact
