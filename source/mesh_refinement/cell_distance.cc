#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <boost/serialization/utility.hpp>

#include <dyncontact/mesh_refinement/cell_distance.h>

#include <cmath>
#include <limits>

namespace dyncontact
{
  namespace MeshRefinement
  {
    namespace
    {
      /// Half the edge of @p cell (of a square or cube of its diameter).
      template <int dim>
      double
      half_size(const typename Triangulation<dim>::active_cell_iterator &cell)
      {
        return 0.5 * cell->diameter() / std::sqrt(double(dim));
      }
    } // namespace



    template <int dim>
    std::vector<double>
    distance_from_cells(const Triangulation<dim> &triangulation,
                        const std::vector<bool>  &seeds,
                        const double              spread)
    {
      using Cell   = typename Triangulation<dim>::active_cell_iterator;
      using Origin = std::pair<Point<dim>, double>; // centre, half size
      const MPI_Comm      comm = triangulation.get_communicator();
      const unsigned int  n    = triangulation.n_active_cells();
      std::vector<Origin> origin(n);
      std::vector<double> reach(n, std::numeric_limits<double>::max());
      std::vector<char>   changed(n, 0);
      std::vector<Cell>   front;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && seeds[cell->active_cell_index()])
          {
            const unsigned int i = cell->active_cell_index();
            origin[i]            = {cell->center(), half_size<dim>(cell)};
            reach[i]             = -std::numeric_limits<double>::max();
            changed[i]           = 1;
            front.push_back(cell);
          }

      // @p cell reached from @p from: true if it is within the spread and
      // nearer than what reached it before
      const auto reached = [&](const Cell &cell, const Origin &from) {
        const unsigned int i = cell->active_cell_index();
        const double d = cell->center().distance(from.first) - from.second -
                         half_size<dim>(cell);
        if (d > spread || d >= reach[i])
          return false;
        origin[i]  = from;
        reach[i]   = d;
        changed[i] = 1;
        return true;
      };

      const auto visit =
        [&](const Cell &neighbor, const Cell &cell, std::vector<Cell> &next) {
          if (neighbor->is_locally_owned() &&
              reached(neighbor, origin[cell->active_cell_index()]))
            next.push_back(neighbor);
        };
      const bool parallel = Utilities::MPI::n_mpi_processes(comm) > 1;
      while (true)
        {
          // over this rank's cells, round by round, as far as it goes
          while (!front.empty())
            {
              std::vector<Cell> next;
              for (const Cell &cell : front)
                for (const unsigned int f : cell->face_indices())
                  if (!cell->at_boundary(f))
                    {
                      const auto neighbor = cell->neighbor(f);
                      if (neighbor->has_children())
                        for (unsigned int s = 0;
                             s < cell->face(f)->n_children();
                             ++s)
                          visit(cell->neighbor_child_on_subface(f, s),
                                cell,
                                next);
                      else
                        visit(neighbor, cell, next);
                    }
              front.swap(next);
            }
          if (!parallel)
            break;
          // what changed on this rank's cells since the last exchange, to
          // the ranks that see them as ghosts: the ghosts it reaches start
          // the next spread there (one exchange per crossing of a rank's
          // boundary, not one per cell of the spread)
          GridTools::exchange_cell_data_to_ghosts<Origin>(
            triangulation,
            [&](const Cell &cell) {
              return changed[cell->active_cell_index()] ?
                       std_cxx17::optional<Origin>(
                         origin[cell->active_cell_index()]) :
                       std_cxx17::optional<Origin>();
            },
            [&](const Cell &cell, const Origin &from) {
              if (reached(cell, from))
                front.push_back(cell);
            });
          std::fill(changed.begin(), changed.end(), 0);
          if (Utilities::MPI::max(front.size(), comm) == 0)
            break;
        }
      return reach;
    }



    template std::vector<double>
    distance_from_cells(const Triangulation<2> &,
                        const std::vector<bool> &,
                        const double);
    template std::vector<double>
    distance_from_cells(const Triangulation<3> &,
                        const std::vector<bool> &,
                        const double);
  } // namespace MeshRefinement
} // namespace dyncontact
