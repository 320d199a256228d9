#ifndef dyncontact_mesh_refinement_cell_distance_h
#define dyncontact_mesh_refinement_cell_distance_h

#include <deal.II/grid/tria.h>

#include <vector>

namespace dyncontact
{
  using namespace dealii;

  namespace MeshRefinement
  {
    /**
     * The distance of each locally owned active cell of @p triangulation
     * from the nearest of the @p seeds (flags by active cell index, each
     * rank's own cells), as far as @p spread: a cell of centre x and half
     * size r is at |x - x'| - r - r' of a seed (x', r') (the distance of
     * the two cells' boxes along the line of their centres; a seed itself
     * is at -max()), a cell beyond @p spread or not reached at max().
     * The distances spread from face neighbour to face neighbour, each
     * cell keeping the nearest seed that reached it, until no cell is
     * reached any more, first over each rank's own cells, then to the ghost
     * cells of the other ranks, where they spread again, until no rank
     * reaches a cell: the work is proportional to the cells within the
     * spread, the exchanges to the times it crosses a rank's boundary.
     * Collective on the triangulation's communicator.
     */
    template <int dim>
    std::vector<double>
    distance_from_cells(const Triangulation<dim> &triangulation,
                        const std::vector<bool>  &seeds,
                        const double              spread);
  } // namespace MeshRefinement
} // namespace dyncontact

#endif
