// What one mesh adaptation's refinement costs in deal.II's distributed
// triangulation (p4est, which the program uses on any number of ranks)
// against its serial Triangulation on one rank (doc/results.md, "Cost of
// a mesh adaptation"). A 2D bar mesh of
// nx x nx/4 cells on [0, 1] x [0, 0.25] (the bar impact's 128 cells along
// with H = 0.25) is refined by two levels in a band of width 0.1 that moves
// by 0.01 per adaptation (a front), and coarsened behind it, 40 times; each
// adaptation transfers two vectors of FE_Q(p)^2 (u and its velocity), as the
// program does (with deal.II's transfers; on the serial triangulation the
// program now uses its own SerialTransfer, the same bits at less cost).
// Printed per adaptation: the refinement with the transfer's
// preparation ('refine'), and the DoFs with the interpolation ('dofs'), for
// both triangulations, and their ratios, measured in one run. One rank,
// Release. Not built by default:
//     cd build && ninja refinement_cost && ./refinement_cost [nx] [p]
// (defaults: 128 and 1).

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/solution_transfer.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>

using namespace dealii;

namespace
{
  constexpr int          dim         = 2;
  constexpr unsigned int adaptations = 40;

  /// Flags the cells of the band [a, a + 0.1] for refinement up to level
  /// 2, the others for coarsening.
  template <typename TriangulationType>
  void
  mark(TriangulationType &triangulation, const double a)
  {
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double x    = cell->center()[0];
          const bool   band = x > a && x < a + 0.1;
          if (band && cell->level() < 2)
            cell->set_refine_flag();
          else if (!band && cell->level() > 0)
            cell->set_coarsen_flag();
        }
  }

  /// The bar mesh of nx x nx/4 cells on [0, 1] x [0, 0.25].
  void
  bar_mesh(Triangulation<dim> &triangulation, const unsigned int nx)
  {
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {nx, nx / 4},
                                              Point<dim>(),
                                              Point<dim>(1., 0.25));
  }

  struct Cost
  {
    double       refine = 0., dofs = 0.;
    unsigned int cells = 0;
  };

  Cost
  serial(const unsigned int nx, const FiniteElement<dim> &fe)
  {
    Triangulation<dim> triangulation;
    bar_mesh(triangulation, nx);
    DoFHandler<dim> dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    std::vector<Vector<double>> state(2, Vector<double>(dof_handler.n_dofs()));
    Cost                        cost;
    for (unsigned int k = 0; k < adaptations; ++k)
      {
        mark(triangulation, 0.2 + 0.01 * k);
        Timer                                 refine;
        SolutionTransfer<dim, Vector<double>> transfer(dof_handler);
        triangulation.prepare_coarsening_and_refinement();
        transfer.prepare_for_coarsening_and_refinement(state);
        triangulation.execute_coarsening_and_refinement();
        cost.refine += refine.wall_time() / adaptations;
        Timer dofs;
        dof_handler.distribute_dofs(fe);
        std::vector<Vector<double>> result(
          2, Vector<double>(dof_handler.n_dofs()));
        transfer.interpolate(state, result);
        state = result;
        cost.dofs += dofs.wall_time() / adaptations;
      }
    cost.cells = triangulation.n_active_cells();
    return cost;
  }

  Cost
  distributed(const unsigned int nx, const FiniteElement<dim> &fe)
  {
    using VectorType = LinearAlgebra::distributed::Vector<double>;
    parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
    bar_mesh(triangulation, nx);
    DoFHandler<dim> dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    const auto vectors = [&]() {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      return std::vector<VectorType>(
        2,
        VectorType(dof_handler.locally_owned_dofs(), relevant, MPI_COMM_WORLD));
    };
    std::vector<VectorType> state = vectors();
    Cost                    cost;
    for (unsigned int k = 0; k < adaptations; ++k)
      {
        mark(triangulation, 0.2 + 0.01 * k);
        Timer                                                    refine;
        parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
          dof_handler);
        triangulation.prepare_coarsening_and_refinement();
        for (auto &v : state)
          v.update_ghost_values();
        transfer.prepare_for_coarsening_and_refinement(
          std::vector<const VectorType *>{&state[0], &state[1]});
        triangulation.execute_coarsening_and_refinement();
        cost.refine += refine.wall_time() / adaptations;
        Timer dofs;
        dof_handler.distribute_dofs(fe);
        std::vector<VectorType>   result  = vectors();
        std::vector<VectorType *> targets = {&result[0], &result[1]};
        transfer.interpolate(targets);
        state = vectors();
        for (unsigned int i = 0; i < 2; ++i)
          state[i] = result[i];
        cost.dofs += dofs.wall_time() / adaptations;
      }
    cost.cells = triangulation.n_global_active_cells();
    return cost;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               nx     = argc > 1 ? std::atoi(argv[1]) : 128;
  const unsigned int               degree = argc > 2 ? std::atoi(argv[2]) : 1;
  if (nx < 4 || nx > 4096 || degree < 1 || degree > 4)
    {
      std::cerr << "usage: refinement_cost [nx in 4..4096] [p in 1..4]\n";
      return 1;
    }
  const FESystem<dim> fe(FE_Q<dim>(degree), dim);
  const Cost          p4est       = distributed(nx, fe);
  const Cost          serial_cost = serial(nx, fe);
  std::cout << std::setprecision(3) << "2D bar, " << nx << " x " << nx / 4
            << " coarse cells, p = " << degree << ", " << p4est.cells
            << " cells at the end (serial: " << serial_cost.cells
            << "), per adaptation:\n"
            << "  refine: distributed " << 1e3 * p4est.refine << " ms, serial "
            << 1e3 * serial_cost.refine << " ms, ratio "
            << p4est.refine / serial_cost.refine << "\n"
            << "  dofs:   distributed " << 1e3 * p4est.dofs << " ms, serial "
            << 1e3 * serial_cost.dofs << " ms, ratio "
            << p4est.dofs / serial_cost.dofs << "\n";
}
