#ifndef dyncontact_scenes_body_overlap_h
#define dyncontact_scenes_body_overlap_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <optional>
#include <set>

namespace dyncontact
{
  using namespace dealii;

  /**
   * Whether @p x lies strictly inside the cell @p cell of a mapping of
   * degree 1 (its unit coordinates more than 1e-8 from 0 and 1): a point on
   * the cell's boundary, where two bodies touch, is not inside.
   */
  template <int dim>
  bool
  strictly_inside(const typename Triangulation<dim>::cell_iterator &cell,
                  const Point<dim>                                 &x);

  /**
   * Whether the point @p x of the reference configuration lies inside one
   * of the bodies @p bodies (material ids) of @p tria: in a cell of their
   * coarse mesh (which every rank holds whole), and on no face of their
   * cells that bounds a body (a point on a face between two cells of a
   * body is inside; a point on a body's boundary, where bodies touch, or
   * at a re-entrant corner, is not). None when a coarse cell or face has a
   * manifold other than the flat one: the finer cells then leave their
   * coarse cells.
   */
  template <int dim>
  std::optional<bool>
  inside_a_body(const Triangulation<dim>           &tria,
                const Point<dim>                   &x,
                const std::set<types::material_id> &bodies);
} // namespace dyncontact

#endif
