#ifndef dyncontact_output_state_comparison_h
#define dyncontact_output_state_comparison_h

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace dyncontact
{
  using namespace dealii;

  template <int dim>
  class Scene;

  template <int dim>
  struct ComparedState;

  /**
   * The difference of this run's state and a state written by another run
   * (write_state_file()) on a mesh of the same coarse mesh, in the physical
   * energy norm ||(e, edot)||_E^2 = 1/2 ||edot||^2_{L2(rho)} + 1/2 a(e, e)
   * (the norm of the exact errors, Postprocess "error energy norm").
   *
   * The other run's mesh must be this run's or a refinement of it (a finer
   * uniform or adapted mesh of the same coarse mesh, of any polynomial
   * degree); the difference is integrated on its cells, where this run's
   * state is prolongated through the nested hierarchy with the element's
   * matrices. On one rank, each cell's values are those of its ancestor in
   * this run's mesh, prolongated along the path of children. On several,
   * this run's state is copied onto a second triangulation and refined
   * there until it has the other run's mesh (cells are refined where the
   * other mesh is finer, found through deal.II's RemotePointEvaluation;
   * p4est's SolutionTransfer moves them between the ranks). Every rank
   * holds only its own cells of both meshes; any number of ranks reads the
   * other run's files.
   */
  template <int dim>
  class StateComparison
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /// @p coarse holds the scene's coarse mesh (as build_mesh() makes it
    /// with coarse_only), with its manifolds.
    StateComparison(const Scene<dim>                   &scene,
                    const Mapping<dim>                 &mapping,
                    std::unique_ptr<Triangulation<dim>> coarse);
    ~StateComparison();

    /// Writes the values of @p u and @p udot (ghosted) on each cell this
    /// rank owns, with the cell's id, to @p file (one file per rank).
    static void
    write_values(const std::string     &file,
                 const DoFHandler<dim> &dof_handler,
                 const VectorType      &u,
                 const VectorType      &udot);

    /// ||(u - u_ref, udot - udot_ref)||_E with (u_ref, udot_ref) of degree
    /// @p reference_degree on the mesh of @p mesh_file (loaded once for all
    /// states of that mesh), their values in @p values_file.<rank>, written
    /// by as many ranks as @p values_checksums has (each file's checksum,
    /// checked before it is read); @p u and @p udot ghosted on @p
    /// dof_handler.
    double
    difference(const std::string              &mesh_file,
               const std::string              &values_file,
               const std::vector<std::string> &values_checksums,
               const unsigned int              reference_degree,
               const DoFHandler<dim>          &dof_handler,
               const VectorType               &u,
               const VectorType               &udot) const;

  private:
    const Scene<dim>                   &scene;
    const Mapping<dim>                 &mapping;
    std::unique_ptr<Triangulation<dim>> coarse;
    /// The reference's mesh and state, and the file of that mesh.
    mutable std::unique_ptr<ComparedState<dim>> reference;
    mutable std::string                         reference_mesh;
    /// On several ranks: the cells of this run's mesh refined in each cycle
    /// to reach the reference's (this rank's), and the meshes they were
    /// found for.
    mutable std::vector<std::vector<CellId>> refinement_cycles;
    mutable std::string                      refinement_key;
  };
} // namespace dyncontact

#endif
