#ifndef dyncontact_discretization_rigid_motions_h
#define dyncontact_discretization_rigid_motions_h

#include <deal.II/base/point.h>

#include <vector>

namespace dyncontact
{
  using namespace dealii;

  template <int dim>
  class SemiDiscreteSystem;

  /// Component @p c at @p x of the infinitesimal rotation e_axis x x about
  /// the origin, x_a e_b - x_b e_a with (axis, a, b) cyclic; the axis is z
  /// in 2D (@p m = 0), and x, y, z for @p m = 0, 1, 2 in 3D.
  template <int dim>
  inline double
  rotation_component(const unsigned int m,
                     const unsigned int c,
                     const Point<dim>  &x)
  {
    const unsigned int axis = (dim == 2) ? 2 : m;
    const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const auto         coordinate = [&](const unsigned int j) {
      return j < dim ? x[j] : 0.;
    };
    return (c == b) ? coordinate(a) : (c == a) ? -coordinate(b) : 0.;
  }

  /**
   * For each of the @p n_bodies bodies: how many independent rigid motions
   * (translations and rotations) its Dirichlet constraints leave free, not
   * counting a single one along which the load f acts (contact may stop
   * that one, as in a Hertz problem whose ball is held only by its load
   * and the block). The motions are compared on the fixed DoFs alone, each
   * scaled to norm 1 there (rotations about the centroid of the fixed
   * DoFs), so that a slender body clamped at a small face counts as held.
   * A static problem (min ½uᵀAu − fᵀu on K_h) with a body for which this
   * is not zero is singular: that body's position is not determined.
   * Collective.
   */
  template <int dim>
  std::vector<unsigned int>
  unheld_rigid_motions(const SemiDiscreteSystem<dim> &system,
                       const unsigned int             n_bodies);
} // namespace dyncontact

#endif
