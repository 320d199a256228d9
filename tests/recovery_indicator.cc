// The gradient-recovery (Zienkiewicz-Zhu) refinement indicator computed
// without a matrix (ElasticOperator::recovery_indicators), on the two-bar
// scene with hanging nodes (one corner of the first bar, and the cells of
// the second bar just left of the plane x = 0.6, refined once more: hanging
// nodes on that plane), for FE_Q(1..3) in 2D and FE_Q(1..2) in 3D:
// - the indicators of a kinked field agree with an independent computation
//   by FEValues (the recovered gradient as the nodal average of the cell
//   gradients weighted by int psi_i, hanging nodes condensed onto their
//   parents and read back from them), to 1e-6 of the largest (the
//   indicators are floats);
// - an affine field (a different one in each component) is recovered
//   exactly, also at the hanging nodes: every indicator vanishes to
//   round-off (relative to the indicators of the kinked field);
// - the field with a kink on the plane x = 0.6 (the gradient jumps there,
//   and only there): exactly the cells that touch the plane get
//   indicators, the same cells as Kelly's face-jump indicator flags.
// The counts are summed over the ranks, and the sum of the squared
// indicators is printed (the same on one and two ranks).

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <dyncontact/core/parameter_file.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/scenes/interface.h>

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace dyncontact;

std::ofstream out("output");

std::string
check_ok(const bool ok)
{
  return ok ? "OK" : "FAILED";
}

constexpr double kink = 0.6;

template <int dim>
class Affine : public Function<dim>
{
public:
  Affine()
    : Function<dim>(dim)
  {}
  double
  value(const Point<dim> &p, const unsigned int c) const override
  {
    double v = 0.3 * c - 0.1;
    for (unsigned int d = 0; d < dim; ++d)
      v += (0.7 - 0.4 * d + 0.25 * c * d - 0.15 * c) * p[d];
    return v;
  }
};

template <int dim>
class Kinked : public Function<dim>
{
public:
  Kinked()
    : Function<dim>(dim)
  {}
  double
  value(const Point<dim> &p, const unsigned int c) const override
  {
    return (c == 0 ? 1. : 0.5) * std::abs(p[0] - kink) + 0.2 * p[dim - 1];
  }
};

template <int dim>
void
check(const unsigned int degree)
{
  const MPI_Comm   comm = MPI_COMM_WORLD;
  ParameterHandler prm;
  declare_all_parameters(prm);
  prm.parse_input_from_string(
    "set Polynomial degree = " + std::to_string(degree) +
    "\n"
    "subsection Scene\n  set Name = two bars\n"
    "  subsection Two bars\n    set Length = 1\n    set Initial gap = 0.1\n"
    "    set Cells along length = 8\n  end\nend\n");
  const auto scene =
    create_scene<dim>(prm, ".", prm.get_integer("Polynomial degree"), true);
  typename SemiDiscreteSystem<dim>::Parameters parameters;
  parameters.degree = degree;

  parallel::distributed::Triangulation<dim> triangulation(comm);
  scene->create_coarse_mesh(triangulation);
  triangulation.refine_global(1);
  // hanging nodes: the cells nearest to one corner (of the first bar)
  // refined once more
  Point<dim> corner;
  for (const auto &cell : triangulation.active_cell_iterators())
    for (unsigned int d = 0; d < dim; ++d)
      corner[d] = std::min(corner[d], cell->center()[d]);
  corner[0] = Utilities::MPI::min(corner[0], comm);
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned() &&
        (cell->center().distance(corner) < 3. * cell->diameter() ||
         (cell->center()[0] < kink && cell->center()[0] > kink - 0.1)))
      cell->set_refine_flag();
  triangulation.execute_coarsening_and_refinement();

  const MappingQ1<dim>    mapping;
  SemiDiscreteSystem<dim> system(parameters, mapping, comm);
  system.setup(triangulation, *scene);
  system.assemble(*scene);

  const auto indicators = [&](const Function<dim> &function, const bool kelly) {
    VectorType field;
    system.reinit_vector(field);
    VectorTools::interpolate(mapping,
                             system.get_dof_handler(),
                             function,
                             field);
    Vector<float> eta(triangulation.n_active_cells());
    if (kelly)
      KellyErrorEstimator<dim>::estimate(mapping,
                                         system.get_dof_handler(),
                                         QGauss<dim - 1>(degree + 1),
                                         {},
                                         system.ghosted(field),
                                         eta);
    else
      system.recovery_indicators(field, eta);
    return eta;
  };
  // the same indicators by FEValues
  const auto reference = [&](const Function<dim> &function) {
    const auto &dof_handler = system.get_dof_handler();
    const auto &fe          = dof_handler.get_fe();
    VectorType  field, weight;
    system.reinit_vector(field);
    system.reinit_vector(weight);
    VectorTools::interpolate(mapping, dof_handler, function, field);
    const VectorType                         x = system.ghosted(field);
    std::vector<VectorType>                  recovered(dim, weight);
    QGauss<dim>                              quadrature(degree + 1);
    FEValues<dim>                            fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values);
    std::vector<std::vector<Tensor<1, dim>>> gradients(
      quadrature.size(), std::vector<Tensor<1, dim>>(dim));
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    Vector<double>                       local_weight(fe.n_dofs_per_cell());
    std::vector<Vector<double>>          local(dim, local_weight);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values.get_function_gradients(x, gradients);
          local_weight = 0.;
          for (auto &l : local)
            l = 0.;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              for (const unsigned int q : fe_values.quadrature_point_indices())
                {
                  const double psi =
                    fe_values.shape_value_component(i, q, c) * fe_values.JxW(q);
                  local_weight(i) += psi;
                  for (unsigned int k = 0; k < dim; ++k)
                    local[k](i) += psi * gradients[q][c][k];
                }
            }
          cell->get_dof_indices(dofs);
          system.get_constraints().distribute_local_to_global(local_weight,
                                                              dofs,
                                                              weight);
          for (unsigned int k = 0; k < dim; ++k)
            system.get_constraints().distribute_local_to_global(local[k],
                                                                dofs,
                                                                recovered[k]);
        }
    weight.compress(VectorOperation::add);
    std::vector<VectorType> recovered_ghosted;
    for (auto &g : recovered)
      {
        g.compress(VectorOperation::add);
        for (const auto i : system.locally_owned_dofs())
          if (!system.get_constraints().is_constrained(i))
            g(i) = g(i) / weight(i);
        g.compress(VectorOperation::insert);
        system.get_constraints().distribute(g);
        recovered_ghosted.push_back(system.ghosted(g));
      }
    Vector<float> eta(triangulation.n_active_cells());
    std::vector<std::vector<Vector<double>>> values(
      dim, std::vector<Vector<double>>(quadrature.size(), Vector<double>(dim)));
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values.get_function_gradients(x, gradients);
          for (unsigned int k = 0; k < dim; ++k)
            fe_values.get_function_values(recovered_ghosted[k], values[k]);
          double squared = 0.;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int c = 0; c < dim; ++c)
                squared += std::pow(values[k][q](c) - gradients[q][c][k], 2) *
                           fe_values.JxW(q);
          eta[cell->active_cell_index()] = std::sqrt(squared);
        }
    return eta;
  };

  const Vector<float> affine = indicators(Affine<dim>(), false);
  const Vector<float> kinked = indicators(Kinked<dim>(), false);
  const Vector<float> kelly  = indicators(Kinked<dim>(), true);
  const double        max_affine =
    Utilities::MPI::max(double(affine.linfty_norm()), comm);
  const double max_kinked =
    Utilities::MPI::max(double(kinked.linfty_norm()), comm);
  const double max_kelly =
    Utilities::MPI::max(double(kelly.linfty_norm()), comm);

  const Vector<float> by_fe_values = reference(Kinked<dim>());
  double              difference = 0., sum_squares = 0.;
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        const unsigned int k = cell->active_cell_index();
        difference =
          std::max(difference, double(std::abs(kinked[k] - by_fe_values[k])));
        sum_squares += double(kinked[k]) * kinked[k];
      }
  difference  = Utilities::MPI::max(difference, comm);
  sum_squares = Utilities::MPI::sum(sum_squares, comm);

  unsigned int n_touching = 0, n_recovery = 0, n_kelly = 0,
               n_recovery_wrong = 0, n_kelly_wrong = 0;
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        bool touches = false;
        for (const unsigned int v : cell->vertex_indices())
          touches |= std::abs(cell->vertex(v)[0] - kink) < 1e-10;
        const bool recovery_flags =
          kinked[cell->active_cell_index()] > 1e-8 * max_kinked;
        const bool kelly_flags =
          kelly[cell->active_cell_index()] > 1e-8 * max_kelly;
        n_touching += touches;
        n_recovery += recovery_flags;
        n_kelly += kelly_flags;
        n_recovery_wrong += (recovery_flags != touches);
        n_kelly_wrong += (kelly_flags != touches);
      }
  const auto sum = [&](const unsigned int n) {
    return Utilities::MPI::sum(n, comm);
  };
  out << dim << "D, degree " << degree << ", "
      << (Utilities::MPI::sum(system.get_constraints().n_constraints(), comm) >
              0 ?
            "with" :
            "without")
      << " hanging nodes, " << triangulation.n_global_active_cells()
      << " cells\n"
      << "  kinked field: the same indicators as by FEValues (to 1e-6 of "
      << "the largest): " << check_ok(difference <= 1e-6 * max_kinked)
      << ", sum of squares " << std::setprecision(4) << sum_squares << "\n"
      << "  affine field: largest indicator <= 1e-10 x the kinked field's: "
      << (max_affine <= 1e-10 * max_kinked ? "OK" : "FAILED") << "\n"
      << "  kinked field: " << sum(n_touching) << " cells touch the kink, "
      << sum(n_recovery) << " have indicators (" << sum(n_recovery_wrong)
      << " elsewhere or missing), Kelly's: " << sum(n_kelly) << " ("
      << sum(n_kelly_wrong) << " elsewhere or missing)\n";
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>(1);
  check<2>(2);
  check<2>(3);
  check<3>(1);
  check<3>(2);
}
