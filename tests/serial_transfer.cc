// The transfer of vectors through a refinement of deal.II's serial
// triangulation (Mesh/Triangulation = serial) against deal.II 9.4's own
// SolutionTransfer, which the program used before: on meshes with hanging
// nodes, cells refined, cells coarsened and cells kept in one adaptation,
// for p = 1, 2, 3 in 2D and 3D, three adaptations in a row (the
// second adds a finest level, the third removes it), two vectors
// transferred at once:
// - the values are equal bit for bit to those of deal.II's transfer of the
//   same Trilinos vectors (the same reads, the same restriction and
//   prolongation matrices, the latter applied with their nonzero entries
//   only, and a DoF shared by cells takes the value of the same cell); the
//   second vector is random and satisfies no hanging-node
//   constraint, so that the cells sharing a DoF give it different values
//   and the order of the writes shows;
// - the transfer of the interpolant of a polynomial of degree p (in the
//   space, so kept by refinement and by coarsening) is its interpolant on
//   the new mesh to round-off.

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/solution_transfer.h>
#include <deal.II/numerics/vector_tools.h>

#include <dyncontact/discretization/serial_transfer.h>

#include <functional>
#include <random>

#include "tests.h"

using namespace dealii;

namespace
{
  /// Component c: a polynomial of degree p in each coordinate, away from 0.
  template <int dim>
  class Polynomial : public Function<dim>
  {
  public:
    Polynomial(const unsigned int p, const double shift)
      : Function<dim>(dim)
      , p(p)
      , shift(shift)
    {}

    double
    value(const Point<dim> &x, const unsigned int c) const override
    {
      double v = 2. + shift + c;
      for (unsigned int d = 0; d < dim; ++d)
        v += (0.3 + 0.1 * d + 0.05 * c) * std::pow(x[d] + shift, p);
      return v;
    }

  private:
    const unsigned int p;
    const double       shift;
  };



  template <int dim>
  void
  run(const unsigned int p)
  {
    Triangulation<dim> tria(
      Triangulation<dim>::limit_level_difference_at_vertices);
    std::vector<unsigned int> cells(dim, 2);
    cells[0] = 4;
    Point<dim> far;
    for (unsigned int d = 0; d < dim; ++d)
      far[d] = (d == 0) ? 2. : 1.;
    GridGenerator::subdivided_hyper_rectangle(tria, cells, Point<dim>(), far);
    tria.refine_global(1);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] < 0.8)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();

    FESystem<dim>   fe(FE_Q<dim>(p), dim);
    DoFHandler<dim> dofs(tria);
    dofs.distribute_dofs(fe);
    using TrilinosVector  = TrilinosWrappers::MPI::Vector;
    const auto new_vector = [&]() {
      return TrilinosVector(complete_index_set(dofs.n_dofs()), MPI_COMM_SELF);
    };
    // the interpolant of the polynomial on the current mesh
    const auto interpolant = [&]() {
      AffineConstraints<double> hanging;
      DoFTools::make_hanging_node_constraints(dofs, hanging);
      hanging.close();
      Vector<double> v(dofs.n_dofs());
      VectorTools::interpolate(dofs, Polynomial<dim>(p, 0.1), v);
      hanging.distribute(v);
      return v;
    };
    std::vector<TrilinosVector> state(2, new_vector());
    {
      const Vector<double>                   v = interpolant();
      std::mt19937                           random(p + 10 * dim);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      for (unsigned int i = 0; i < v.size(); ++i)
        {
          state[0][i] = v[i];
          state[1][i] = uniform(random);
        }
      for (auto &vector : state)
        vector.compress(VectorOperation::insert);
    }

    // three adaptations: the finest cells near x = 0 coarsened and a band
    // around x = 1 refined; a new finest level in it; that level removed
    // again by coarsening and another band refined
    const std::vector<std::function<void(
      const typename Triangulation<dim>::active_cell_iterator &)>>
      flags = {[](const auto &cell) {
                 if (cell->level() == 2 && cell->center()[0] < 0.25)
                   cell->set_coarsen_flag();
                 else if (cell->center()[0] > 0.9 && cell->center()[0] < 1.3)
                   cell->set_refine_flag();
               },
               [](const auto &cell) {
                 if (cell->center()[0] > 1.0 && cell->center()[0] < 1.2)
                   cell->set_refine_flag();
               },
               [](const auto &cell) {
                 if (cell->level() == 3)
                   cell->set_coarsen_flag();
                 else if (cell->center()[0] > 1.5 && cell->center()[0] < 1.8)
                   cell->set_refine_flag();
               }};
    for (unsigned int a = 0; a < flags.size(); ++a)
      {
        const unsigned int n_before      = tria.n_active_cells();
        const unsigned int levels_before = tria.n_levels();
        unsigned int       n_refine = 0, n_coarsen = 0;
        for (const auto &cell : tria.active_cell_iterators())
          flags[a](cell);
        tria.prepare_coarsening_and_refinement();
        for (const auto &cell : tria.active_cell_iterators())
          {
            n_refine += cell->refine_flag_set() ? 1 : 0;
            n_coarsen += cell->coarsen_flag_set() ? 1 : 0;
          }

        // deal.II's transfer on the Trilinos vectors, as the program used it
        SolutionTransfer<dim, TrilinosVector> reference(dofs);
        reference.prepare_for_coarsening_and_refinement(state);
        dyncontact::SerialTransfer<dim> transfer;
        transfer.prepare(dofs, {&state[0], &state[1]});
        tria.execute_coarsening_and_refinement();
        dofs.distribute_dofs(fe);

        std::vector<TrilinosVector> expected(2, new_vector());
        reference.interpolate(state, expected);
        std::vector<TrilinosVector> transferred(2, new_vector());
        transfer.interpolate(dofs, {&transferred[0], &transferred[1]});

        bool                 equal = true;
        double               error = 0.;
        const Vector<double> exact = interpolant();
        for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
          {
            for (unsigned int j = 0; j < 2; ++j)
              equal = equal && (transferred[j][i] == expected[j][i]);
            error = std::max(error, std::abs(transferred[0][i] - exact[i]));
          }
        testing::log()
          << dim << "D p = " << p << ", adaptation " << a + 1 << ": cells "
          << n_before << " -> " << tria.n_active_cells() << ", levels "
          << levels_before << " -> " << tria.n_levels() << " (" << n_refine
          << " refined, " << n_coarsen << " coarsened), " << dofs.n_dofs()
          << " DoFs: equal to deal.II's SolutionTransfer bit for bit: "
          << testing::check(equal)
          << "; the polynomial's interpolant kept (error < 1e-12): "
          << testing::check(error < 1e-12) << "\n";
        state = std::move(transferred);
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int p : {1, 2, 3})
    run<2>(p);
  for (const unsigned int p : {1, 2, 3})
    run<3>(p);
}
