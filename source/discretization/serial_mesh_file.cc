#include <deal.II/base/exceptions.h>
#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/vector.h>

#include <dyncontact/discretization/serial_mesh_file.h>

#include <cstdint>
#include <fstream>
#include <functional>

namespace dyncontact::SerialMeshFile
{
  namespace
  {
    const std::string magic = "dyncontact serial mesh 1\n";

    /// @p visit on every cell of @p dof_handler's triangulation, depth first
    /// from each coarse cell in order.
    template <int dim, typename Visitor>
    void
    depth_first(const DoFHandler<dim> &dof_handler, const Visitor &visit)
    {
      using Cell = typename DoFHandler<dim>::cell_iterator;
      const std::function<void(const Cell &)> descend = [&](const Cell &cell) {
        visit(cell);
        if (cell->has_children())
          for (unsigned int c = 0; c < cell->n_children(); ++c)
            descend(cell->child(c));
      };
      for (auto cell = dof_handler.begin(0); cell != dof_handler.end(0); ++cell)
        descend(cell);
    }

    void
    write_count(std::ostream &out, const std::uint64_t n)
    {
      out.write(reinterpret_cast<const char *>(&n), sizeof(n));
    }

    std::uint64_t
    read_count(std::istream &in, const std::string &file)
    {
      std::uint64_t n = 0;
      in.read(reinterpret_cast<char *>(&n), sizeof(n));
      AssertThrow(in.good(),
                  ExcMessage("The checkpoint's mesh file '" + file +
                             "' ends early."));
      return n;
    }

    /// The file's refinement bits; @p in stands at the counts after them.
    std::vector<char>
    read_header(std::ifstream &in, const std::string &file)
    {
      std::string head(magic.size(), '\0');
      in.read(head.data(), head.size());
      AssertThrow(in.good() && head == magic,
                  ExcMessage("'" + file +
                             "' is not the mesh of a checkpoint written "
                             "with Mesh/Triangulation = serial."));
      // (a count larger than the file is damage, not a size to allocate)
      const std::streampos here = in.tellg();
      in.seekg(0, std::ios::end);
      const std::uint64_t rest = in.tellg() - here;
      in.seekg(here);
      const std::uint64_t n = read_count(in, file);
      AssertThrow(n <= rest,
                  ExcMessage("The checkpoint's mesh file '" + file +
                             "' is damaged: it claims " + std::to_string(n) +
                             " cells, more than its size allows."));
      std::vector<char> bits(n);
      in.read(bits.data(), bits.size());
      AssertThrow(in.good(),
                  ExcMessage("The checkpoint's mesh file '" + file +
                             "' ends early."));
      return bits;
    }
  } // namespace



  template <int dim>
  void
  write(const std::string                                        &file,
        const DoFHandler<dim>                                    &dof_handler,
        const std::vector<const TrilinosWrappers::MPI::Vector *> &vectors)
  {
    std::vector<char> bits;
    depth_first(dof_handler, [&](const auto &cell) {
      bits.push_back(cell->has_children() ? 1 : 0);
    });
    std::ofstream out(file, std::ios::binary);
    out.write(magic.data(), magic.size());
    write_count(out, bits.size());
    out.write(bits.data(), bits.size());
    write_count(out, vectors.size());
    write_count(out, dof_handler.get_fe().n_dofs_per_cell());
    Vector<double> values(dof_handler.get_fe().n_dofs_per_cell());
    depth_first(dof_handler, [&](const auto &cell) {
      if (cell->is_active())
        for (const auto *v : vectors)
          {
            cell->get_dof_values(*v, values);
            out.write(reinterpret_cast<const char *>(values.data()),
                      values.size() * sizeof(double));
          }
    });
    out.close();
    AssertThrow(out.good(),
                ExcMessage("Cannot write the checkpoint's mesh file '" + file +
                           "'."));
  }



  template <int dim>
  void
  read_refinement(const std::string &file, Triangulation<dim> &triangulation)
  {
    std::ifstream           in(file, std::ios::binary);
    const std::vector<char> bits = read_header(in, file);
    const std::string       mismatch =
      "The checkpoint's mesh file '" + file +
      "' does not fit this run's coarse mesh (its refinement is that of "
      "another mesh).";
    using Cell = typename Triangulation<dim>::cell_iterator;
    std::size_t                 pos  = 0;
    const std::function<void()> skip = [&]() {
      AssertThrow(pos < bits.size(), ExcMessage(mismatch));
      if (bits[pos++] == 1)
        for (unsigned int c = 0; c < GeometryInfo<dim>::max_children_per_cell;
             ++c)
          skip();
    };
    // level by level: each pass refines the active cells that have children
    // in the file, and skips what lies below them
    bool                                    flagged = true;
    const std::function<void(const Cell &)> visit   = [&](const Cell &cell) {
      AssertThrow(pos < bits.size(), ExcMessage(mismatch));
      const bool refined = bits[pos++] == 1;
      AssertThrow(refined || !cell->has_children(), ExcMessage(mismatch));
      if (!refined)
        return;
      if (cell->has_children())
        for (unsigned int c = 0; c < cell->n_children(); ++c)
          visit(cell->child(c));
      else
        {
          cell->set_refine_flag();
          flagged = true;
          // (an active cell has no children yet: n_children() is 0)
          for (unsigned int c = 0; c < GeometryInfo<dim>::max_children_per_cell;
               ++c)
            skip();
        }
    };
    while (flagged)
      {
        flagged = false;
        pos     = 0;
        for (auto cell = triangulation.begin(0); cell != triangulation.end(0);
             ++cell)
          visit(cell);
        AssertThrow(pos == bits.size(), ExcMessage(mismatch));
        if (flagged)
          triangulation.execute_coarsening_and_refinement();
      }
  }



  template <int dim>
  void
  read_vectors(const std::string                                  &file,
               const DoFHandler<dim>                              &dof_handler,
               const std::vector<TrilinosWrappers::MPI::Vector *> &vectors)
  {
    std::ifstream in(file, std::ios::binary);
    read_header(in, file);
    const std::uint64_t n_vectors     = read_count(in, file);
    const std::uint64_t dofs_per_cell = read_count(in, file);
    AssertThrow(
      n_vectors == vectors.size() &&
        dofs_per_cell == dof_handler.get_fe().n_dofs_per_cell(),
      ExcMessage("The checkpoint's mesh file '" + file + "' holds " +
                 std::to_string(n_vectors) + " vectors of " +
                 std::to_string(dofs_per_cell) +
                 " values per cell, this run expects " +
                 std::to_string(vectors.size()) + " of " +
                 std::to_string(dof_handler.get_fe().n_dofs_per_cell()) + "."));
    Vector<double> values(dofs_per_cell);
    depth_first(dof_handler, [&](const auto &cell) {
      if (cell->is_active())
        for (auto *v : vectors)
          {
            in.read(reinterpret_cast<char *>(values.data()),
                    values.size() * sizeof(double));
            AssertThrow(in.good(),
                        ExcMessage("The checkpoint's mesh file '" + file +
                                   "' ends early."));
            cell->set_dof_values(values, *v);
          }
    });
    for (auto *v : vectors)
      v->compress(VectorOperation::insert);
  }



  template void
  write<2>(const std::string &,
           const DoFHandler<2> &,
           const std::vector<const TrilinosWrappers::MPI::Vector *> &);
  template void
  write<3>(const std::string &,
           const DoFHandler<3> &,
           const std::vector<const TrilinosWrappers::MPI::Vector *> &);
  template void
  read_refinement<2>(const std::string &, Triangulation<2> &);
  template void
  read_refinement<3>(const std::string &, Triangulation<3> &);
  template void
  read_vectors<2>(const std::string &,
                  const DoFHandler<2> &,
                  const std::vector<TrilinosWrappers::MPI::Vector *> &);
  template void
  read_vectors<3>(const std::string &,
                  const DoFHandler<3> &,
                  const std::vector<TrilinosWrappers::MPI::Vector *> &);
} // namespace dyncontact::SerialMeshFile
