// The matrix-free elastic and viscous forms (ElasticOperator) against the
// assembled matrices of SemiDiscreteSystem::assemble_stiffness_matrix: the
// time step's matrix S = a A + b B + m M is assembled, while A x and B x of
// the right-hand side and the energies are computed without a matrix, and
// Theorem 3.2 needs both to be the same form on the constrained space (the
// states of a run satisfy the constraints). Two bars of different
// viscoelastic materials in 2D and 3D, FE_Q(1) and FE_Q(2), and in 2D also
// FE_Q(3), with hanging nodes (one corner of the mesh refined once more);
// random vectors. Also the lumped mass, which the assembly adds on the diagonal
// in the cell loop, once per row. (The sparsity pattern comes from the scalar
// element's where the vector DoFs are the scalar ones expanded, as for degrees
// 1 and 2, and from the vector element's otherwise, as for degree 3: an entry
// missing from either would stop the assembly.) Also what 'Contact
// solver/Step matrix = matrix-free' uses: a A + b B in one pass, and its
// diagonal computed cell by cell without the matrix.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/mapping_q1.h>

#include <dyncontact/contact/active_set_solver.h>
#include <dyncontact/core/parameter_file.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/scenes/interface.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace dyncontact;

std::ofstream out("output");

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
    // (8 cells along, 2 across: the forms agree on any mesh)
    "  subsection Two bars\n    set Cells along length = 8\n"
    "    set Height = 0.25\n  end\nend\n"
    "subsection Material\n  set Young's modulus = 2\n"
    "  set Poisson's ratio = 0.3\n  set Density = 3\n"
    "  set Viscous shear modulus = 0.5\n  set Viscous Lame parameter = 0.2\n"
    "end\n"
    "subsection Material of body 2\n  set Young's modulus = 7\n"
    "  set Poisson's ratio = 0.1\n  set Viscous shear modulus = 0.05\nend\n");
  const auto scene =
    create_scene<dim>(prm, ".", prm.get_integer("Polynomial degree"), true);
  typename SemiDiscreteSystem<dim>::Parameters parameters;
  parameters.degree = degree;

  parallel::distributed::Triangulation<dim> triangulation(comm);
  scene->create_coarse_mesh(triangulation);
  triangulation.refine_global(1);
  // hanging nodes: the cells nearest to one corner refined once more
  Point<dim> corner;
  for (const auto &cell : triangulation.active_cell_iterators())
    for (unsigned int d = 0; d < dim; ++d)
      corner[d] = std::min(corner[d], cell->center()[d]);
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned() &&
        cell->center().distance(corner) < 3. * cell->diameter())
      cell->set_refine_flag();
  triangulation.execute_coarsening_and_refinement();

  const MappingQ1<dim>    mapping;
  SemiDiscreteSystem<dim> system(parameters, mapping, comm);
  system.setup(triangulation, *scene);
  system.assemble(*scene);

  // random x and w that satisfy the constraints (hanging nodes follow
  // their parents, as every state of a run does)
  VectorType x, w, y_matrix, y_free, tmp;
  system.reinit_vector(x);
  system.reinit_vector(w);
  std::mt19937                           random(42);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  for (const auto i : system.locally_owned_dofs())
    {
      x(i) = uniform(random);
      w(i) = uniform(random);
    }
  x.compress(VectorOperation::insert);
  w.compress(VectorOperation::insert);
  system.get_constraints().distribute(x);
  system.get_constraints().distribute(w);
  y_matrix = x;
  y_free   = x;
  tmp      = x;

  // |w^T y_matrix - w^T y_free| / (|w| |y_matrix|) for the matrix
  // a A + b B + m M and the matrix-free a A x + b B x + m M x: the forms
  // on the constrained space. (On a mesh with hanging nodes, deal.II's
  // MatrixFree reads a hanging DoF from its parents and adds its row to
  // theirs: the same form there, but not the same vector.)
  const auto difference = [&](const double a, const double b, const double m) {
    MatrixType matrix;
    system.assemble_stiffness_matrix(matrix, a, b, m);
    matrix.vmult(y_matrix, x);
    system.stiffness_vmult(y_free, x);
    y_free *= a;
    system.viscous_vmult(tmp, x);
    y_free.add(b, tmp);
    system.matrices().mass_vmult(tmp, x);
    y_free.add(m, tmp);
    return std::abs(w * y_matrix - w * y_free) /
           (w.l2_norm() * y_matrix.l2_norm());
  };
  const double tolerance = 1e-13;
  out << dim << "D, degree " << degree << ", "
      << (Utilities::MPI::sum(system.get_constraints().n_constraints(), comm) >
              0 ?
            "with" :
            "without")
      << " constrained DoFs, viscous: " << (system.is_viscous() ? "yes" : "no")
      << "\n";
  for (const auto &[name, a, b, m] :
       std::vector<std::tuple<std::string, double, double, double>>{
         {"A", 1., 0., 0.},
         {"B", 0., 1., 0.},
         {"0.3 A + 0.2 B + M (lumped)", 0.3, 0.2, 1.}})
    {
      const double d = difference(a, b, m);
      out << "  " << name << ": matrix and matrix-free agree to " << tolerance
          << ": " << (d <= tolerance ? "OK" : "FAILED")
          << (d <= tolerance ? "" : " (" + std::to_string(d) + ")") << "\n";
    }

  // 'Contact solver/Step matrix = matrix-free': a A + b B in one pass over
  // the cells, and its diagonal computed without the matrix (the same as
  // the assembled matrix's, hanging DoFs included)
  MatrixType matrix;
  system.assemble_stiffness_matrix(matrix, 0.3, 0.2, 0.);
  matrix.vmult(y_matrix, x);
  system.matrices().stiffness_combination_vmult(y_free, x, 0.3, 0.2);
  const double combined =
    std::abs(w * y_matrix - w * y_free) / (w.l2_norm() * y_matrix.l2_norm());
  out << "  0.3 A + 0.2 B in one pass: matrix and matrix-free agree to "
      << tolerance << ": " << (combined <= tolerance ? "OK" : "FAILED") << "\n";
  VectorType       diagonal;
  const VectorType reference = matrix_diagonal(matrix);
  system.stiffness_diagonal(diagonal, 0.3, 0.2);
  diagonal -= reference;
  const double diagonal_error =
    diagonal.linfty_norm() / reference.linfty_norm();
  out << "  its diagonal without the matrix agrees with the matrix's to "
      << tolerance << ": " << (diagonal_error <= tolerance ? "OK" : "FAILED")
      << "\n";
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
