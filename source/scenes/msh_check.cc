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
#include <utility>
#include <vector>

namespace dyncontact
{
  using namespace dealii;

  namespace
  {
    /// Nodes per element of the Gmsh element types.
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



    /**
     * Checks that the file @p name exists and is a regular, readable and
     * non-empty file, and opens it. The messages name it as @p file.
     */
    std::ifstream
    open_msh_file(const std::string &name, const std::string &file)
    {
      AssertThrow(std::filesystem::exists(name),
                  ExcMessage(file + " does not exist."));
      AssertThrow(std::filesystem::is_regular_file(name),
                  ExcMessage(file + " is not a regular file."));
      std::ifstream in(name);
      AssertThrow(in.good(), ExcMessage(file + " cannot be opened."));
      AssertThrow(std::filesystem::file_size(name) > 0,
                  ExcMessage(file + " is empty."));
      return in;
    }



    /**
     * A .msh file read line by line. Its errors name the file, the number
     * of the current line and the line itself.
     */
    struct MshReader
    {
      /// Opens the file @p name (see open_msh_file()).
      explicit MshReader(const std::string &name)
        : name(name)
        , file("Scene/Gmsh/Mesh file '" + name + "'")
        , in(open_msh_file(name, file))
      {}

      /// Reads the next line, without a trailing '\r'; false at the end.
      bool
      read_line()
      {
        if (!std::getline(in, line))
          return false;
        ++line_number;
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        return true;
      }

      /// The next line as a stream; throws if the file ends before it.
      std::istringstream
      next(const std::string &what)
      {
        AssertThrow(read_line(),
                    ExcMessage(file + " ends at line " +
                               std::to_string(line_number) + " while " + what +
                               " were expected: the file is truncated."));
        return std::istringstream(line);
      }

      /// Throws the error @p what about the current line.
      void
      fail(const std::string &what) const
      {
        AssertThrow(false,
                    ExcMessage(file + ", line " + std::to_string(line_number) +
                               ": " + what + " (the line reads '" +
                               line.substr(0, 80) + "')."));
      }

      /// Reads the (non-negative) number of @p what from @p s.
      std::size_t
      read_count(std::istringstream &s, const std::string &what) const
      {
        long long n = -1;
        s >> n;
        if (s.fail() || n < 0)
          fail("expected the number of " + what);
        return std::size_t(n);
      }

      /// Reads the line @p end that closes a section.
      void
      read_end(const std::string &end)
      {
        if (next(end).str() != end)
          fail("expected " + end);
      }

      const std::string name;
      const std::string file;
      std::ifstream     in;
      std::string       line;
      std::size_t       line_number = 0;
    };



    /**
     * Checks that the Gmsh element type @p type is supported: points,
     * lines, quadrilaterals and (3D) hexahedra of first order.
     */
    void
    check_element_type(const MshReader &reader, const int type, const int dim)
    {
      if (type == 15 || type == 1 || type == 3 || (dim == 3 && type == 5))
        return;
      if (type == 2 || type == 4 || type == 6 || type == 7)
        reader.fail(
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
      reader.fail("element type " + std::to_string(type) +
                  " is not supported: only first-order points, lines, "
                  "quadrilaterals and (3D) hexahedra");
    }



    /// Reads the $MeshFormat section; returns the major version (2 or 4).
    int
    read_mesh_format(MshReader &reader)
    {
      auto   s      = reader.next("the format");
      double format = 0.;
      int    binary = -1;
      s >> format >> binary;
      if (s.fail())
        reader.fail("expected 'version file-type data-size'");
      if (binary != 0)
        reader.fail("binary .msh files are not supported; save the mesh "
                    "as ASCII (gmsh -save -format msh2 or msh4)");
      const int version = int(format);
      if (version != 2 && version != 4)
        reader.fail("the .msh format " + std::to_string(format) +
                    " is not supported (2.2 and 4.1 are)");
      return version;
    }



    /**
     * Reads the line @p what that starts $Nodes or $Elements; returns the
     * number of blocks (@p blocks, only in format 4, else 1) and of
     * nodes or elements (@p items).
     */
    std::pair<std::size_t, std::size_t>
    read_counts(MshReader         &reader,
                const int          version,
                const std::string &what,
                const std::string &blocks,
                const std::string &items)
    {
      auto        s        = reader.next(what);
      std::size_t n_blocks = 1;
      if (version == 4)
        n_blocks = reader.read_count(s, blocks);
      const std::size_t n = reader.read_count(s, items);
      return {n_blocks, n};
    }



    /// Reads the header of a node block (format 4) and the node tags.
    std::vector<long long>
    read_node_tags(MshReader &reader)
    {
      auto sb = reader.next("a node block header");
      int  entity_dim, entity_tag, parametric;
      sb >> entity_dim >> entity_tag >> parametric;
      const std::size_t in_block = reader.read_count(sb, "nodes in the block");
      if (parametric != 0)
        reader.fail("parametric nodes are not supported");
      std::vector<long long> tags;
      for (std::size_t k = 0; k < in_block; ++k)
        {
          auto      st  = reader.next("node tags");
          long long tag = -1;
          st >> tag;
          if (st.fail())
            reader.fail("expected a node tag");
          tags.push_back(tag);
        }
      return tags;
    }



    /**
     * Reads a block of nodes (format 4) or all @p n nodes (format 2),
     * checks their coordinates and adds their tags to @p node_ids. Returns
     * the number of nodes read.
     */
    std::size_t
    read_node_block(MshReader                     &reader,
                    const int                      version,
                    const std::size_t              n,
                    std::unordered_set<long long> &node_ids)
    {
      std::vector<long long> tags;
      if (version == 4)
        tags = read_node_tags(reader);
      const std::size_t in_block = (version == 4 ? tags.size() : n);
      for (std::size_t k = 0; k < in_block; ++k)
        {
          auto      sn = reader.next("nodes");
          long long id = 0;
          if (version == 2)
            sn >> id;
          else
            id = tags[k];
          std::string x[3];
          sn >> x[0] >> x[1] >> x[2];
          if (sn.fail())
            reader.fail("expected a node with three coordinates");
          for (const auto &c : x)
            {
              char  *end   = nullptr;
              double value = std::strtod(c.c_str(), &end);
              if (*end != '\0' || !std::isfinite(value))
                reader.fail("the coordinate '" + c +
                            "' is not a finite number");
            }
          node_ids.insert(id);
        }
      return in_block;
    }



    /// Reads a $Nodes section and adds the node tags to @p node_ids.
    void
    read_nodes(MshReader                     &reader,
               const int                      version,
               std::unordered_set<long long> &node_ids)
    {
      const auto [blocks, n] =
        read_counts(reader, version, "the node counts", "node blocks", "nodes");
      if (std::min<std::size_t>(n, 1u << 20) >
          std::filesystem::file_size(reader.name))
        reader.fail("more nodes than the file could hold");
      std::size_t read = 0;
      for (std::size_t b = 0; b < blocks; ++b)
        read += read_node_block(reader, version, n, node_ids);
      if (read != n)
        reader.fail("the node blocks hold " + std::to_string(read) +
                    " nodes, the header says " + std::to_string(n));
      reader.read_end("$EndNodes");
    }



    /**
     * Reads one element line; checks its type (format 2; in format 4 the
     * block header has @p block_type) and that its nodes are in
     * @p node_ids. Returns the type of the element.
     */
    int
    read_element(MshReader                           &reader,
                 const int                            version,
                 const int                            dim,
                 const int                            block_type,
                 const std::unordered_set<long long> &node_ids)
    {
      int       type = block_type;
      auto      se   = reader.next("elements");
      long long id   = 0;
      se >> id;
      if (version == 2)
        {
          int n_tags = 0;
          se >> type >> n_tags;
          if (se.fail() || n_tags < 0)
            reader.fail("expected 'id type number-of-tags ...'");
          check_element_type(reader, type, dim);
          for (int t = 0; t < n_tags; ++t)
            se >> id;
        }
      const auto nodes_of = nodes_per_element.find(type);
      for (unsigned int v = 0; v < nodes_of->second; ++v)
        {
          long long node = 0;
          se >> node;
          if (se.fail())
            reader.fail("expected " + std::to_string(nodes_of->second) +
                        " node tags of the element");
          if (node_ids.count(node) == 0)
            reader.fail("the element refers to node " + std::to_string(node) +
                        ", which $Nodes does not define");
        }
      return type;
    }



    /**
     * Reads an $Elements section whose nodes must be in @p node_ids;
     * returns the number of cells (quadrilaterals in 2D, hexahedra in 3D).
     */
    std::size_t
    read_elements(MshReader                           &reader,
                  const int                            version,
                  const int                            dim,
                  const std::unordered_set<long long> &node_ids)
    {
      const auto [blocks, n] = read_counts(
        reader, version, "the element counts", "element blocks", "elements");
      std::size_t n_cells = 0;
      for (std::size_t b = 0; b < blocks; ++b)
        {
          std::size_t in_block = n;
          int         type     = 0;
          if (version == 4)
            {
              auto sb = reader.next("an element block header");
              int  entity_dim, entity_tag;
              sb >> entity_dim >> entity_tag >> type;
              in_block = reader.read_count(sb, "elements in the block");
              check_element_type(reader, type, dim);
            }
          for (std::size_t k = 0; k < in_block; ++k)
            if (read_element(reader, version, dim, type, node_ids) ==
                (dim == 2 ? 3 : 5))
              ++n_cells;
        }
      reader.read_end("$EndElements");
      return n_cells;
    }
  } // namespace



  std::size_t
  check_msh_file(const std::string &name, const int dim)
  {
    MshReader                     reader(name);
    int                           version = 0;
    bool                          nodes = false, elements = false;
    std::size_t                   n_cells = 0;
    std::unordered_set<long long> node_ids;
    while (reader.read_line())
      {
        if (reader.line == "$MeshFormat")
          version = read_mesh_format(reader);
        else if (reader.line == "$Nodes")
          {
            if (version == 0)
              reader.fail("$Nodes before $MeshFormat: this is no .msh file");
            read_nodes(reader, version, node_ids);
            nodes = true;
          }
        else if (reader.line == "$Elements")
          {
            if (!nodes)
              reader.fail("$Elements before $Nodes");
            n_cells += read_elements(reader, version, dim, node_ids);
            elements = true;
          }
      }
    AssertThrow(version != 0,
                ExcMessage(reader.file +
                           " has no $MeshFormat section: it is no "
                           "Gmsh .msh file."));
    AssertThrow(nodes && elements,
                ExcMessage(reader.file + " has no " +
                           (nodes ? "$Elements" : "$Nodes") +
                           " section: the file is truncated."));
    AssertThrow(n_cells > 0,
                ExcMessage(reader.file + " has no " +
                           (dim == 2 ? "quadrilaterals" : "hexahedra") +
                           ": is it a mesh for the other dimension (set "
                           "Dimension)?"));
    return n_cells;
  }
} // namespace dyncontact
