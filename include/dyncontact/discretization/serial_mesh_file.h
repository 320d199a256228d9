#ifndef dyncontact_discretization_serial_mesh_file_h
#define dyncontact_discretization_serial_mesh_file_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

/**
 * The checkpoint of a mesh held by deal.II's serial Triangulation
 * (Mesh/Triangulation = serial), in place of p4est's files: the refinement
 * of each coarse cell, depth first (1: has children), and the values of
 * the saved vectors on every active cell in the same order. Neither
 * depends on the numbering of cells or DoFs, which the history of
 * refinement and coarsening decides: a resumed run rebuilds the same mesh
 * on the same coarse mesh and reads the values cell by cell.
 */
namespace dyncontact::SerialMeshFile
{
  using namespace dealii;

  /// Writes the refinement of @p dof_handler's triangulation and @p vectors
  /// (each with every value, i.e. on one rank) into @p file.
  template <int dim>
  void
  write(const std::string                                        &file,
        const DoFHandler<dim>                                    &dof_handler,
        const std::vector<const TrilinosWrappers::MPI::Vector *> &vectors);

  /// Refines @p triangulation, which holds the coarse mesh of the run that
  /// wrote @p file, to that run's mesh.
  template <int dim>
  void
  read_refinement(const std::string &file, Triangulation<dim> &triangulation);

  /// After read_refinement() and the DoFs: the vectors of @p file, in the
  /// order and number they were written (@p vectors sized, without
  /// ghosts).
  template <int dim>
  void
  read_vectors(const std::string                                  &file,
               const DoFHandler<dim>                              &dof_handler,
               const std::vector<TrilinosWrappers::MPI::Vector *> &vectors);
} // namespace dyncontact::SerialMeshFile

#endif
