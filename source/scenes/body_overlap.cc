// Points inside bodies, on the coarse mesh.

#include <deal.II/base/bounding_box.h>
#include <deal.II/fe/mapping_q.h>

#include <dyncontact/scenes/body_overlap.h>

namespace dyncontact
{
  namespace
  {
    /// The point @p x on the unit cell of @p cell (a mapping of degree 1),
    /// if it lies in the cell's bounding box.
    template <int dim>
    std::optional<Point<dim>>
    unit_point(const typename Triangulation<dim>::cell_iterator &cell,
               const Point<dim>                                 &x)
    {
      if (!cell->bounding_box().point_inside(x, 1e-10))
        return {};
      static const MappingQ<dim> mapping(1);
      try
        {
          return mapping.transform_real_to_unit_cell(cell, x);
        }
      catch (...)
        {
          // (the Newton iteration failed in a distorted cell: not in it)
          return {};
        }
    }
  } // namespace



  template <int dim>
  bool
  strictly_inside(const typename Triangulation<dim>::cell_iterator &cell,
                  const Point<dim>                                 &x)
  {
    const auto unit = unit_point<dim>(cell, x);
    if (!unit)
      return false;
    for (unsigned int d = 0; d < dim; ++d)
      if (!((*unit)[d] > 1e-8 && (*unit)[d] < 1. - 1e-8))
        return false;
    return true;
  }



  template <int dim>
  std::optional<bool>
  inside_a_body(const Triangulation<dim>           &tria,
                const Point<dim>                   &x,
                const std::set<types::material_id> &bodies)
  {
    for (const auto &cell : tria.cell_iterators_on_level(0))
      {
        if (cell->manifold_id() != numbers::flat_manifold_id)
          return {};
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->manifold_id() != numbers::flat_manifold_id)
            return {};
      }
    // in a cell of the bodies, or on its faces between two of their cells,
    // and on none of their boundary faces
    bool inside = false;
    for (const auto &cell : tria.cell_iterators_on_level(0))
      if (bodies.count(cell->material_id()) > 0)
        if (const auto unit = unit_point<dim>(cell, x))
          {
            bool in_closure = true;
            for (unsigned int d = 0; d < dim; ++d)
              in_closure =
                in_closure && (*unit)[d] > -1e-8 && (*unit)[d] < 1. + 1e-8;
            if (!in_closure)
              continue;
            for (unsigned int d = 0; d < dim; ++d)
              if (((*unit)[d] < 1e-8 && cell->face(2 * d)->at_boundary()) ||
                  ((*unit)[d] > 1. - 1e-8 &&
                   cell->face(2 * d + 1)->at_boundary()))
                return false;
            inside = true;
          }
    return inside;
  }



  template bool
  strictly_inside<2>(const Triangulation<2>::cell_iterator &, const Point<2> &);
  template bool
  strictly_inside<3>(const Triangulation<3>::cell_iterator &, const Point<3> &);
  template std::optional<bool>
  inside_a_body(const Triangulation<2> &,
                const Point<2> &,
                const std::set<types::material_id> &);
  template std::optional<bool>
  inside_a_body(const Triangulation<3> &,
                const Point<3> &,
                const std::set<types::material_id> &);
} // namespace dyncontact
