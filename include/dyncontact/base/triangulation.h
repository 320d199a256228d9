#ifndef dyncontact_base_triangulation_h
#define dyncontact_base_triangulation_h

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/tria.h>

#include <memory>

/**
 * Which triangulation holds the mesh (Mesh/Triangulation): p4est's
 * parallel::distributed::Triangulation, or deal.II's serial Triangulation on
 * one rank. The one place that makes it and tells the two apart.
 */
namespace dyncontact
{
  using namespace dealii;

  /// A new, empty triangulation: deal.II's serial one if @p serial (with
  /// limit_level_difference_at_vertices, p4est's 2:1 balance across faces
  /// and vertices, so that both refine to the same meshes), else p4est's on
  /// @p comm.
  /// (DiscreteProblem::adapt_mesh() skips the smoothing of the flags when
  /// no cell is flagged: with these smoothings it has nothing to add to a
  /// mesh that came out of a refinement. One that adds flags by itself,
  /// e.g. coarsest_level_1, would need it run.)
  template <int dim>
  std::unique_ptr<Triangulation<dim>>
  make_triangulation(const bool serial, const MPI_Comm comm)
  {
    if (serial)
      return std::make_unique<Triangulation<dim>>(
        Triangulation<dim>::limit_level_difference_at_vertices);
    return std::make_unique<parallel::distributed::Triangulation<dim>>(comm);
  }

  /// @p triangulation as p4est's, or nullptr if it is deal.II's serial one.
  template <int dim>
  parallel::distributed::Triangulation<dim> *
  as_distributed(Triangulation<dim> &triangulation)
  {
    return dynamic_cast<parallel::distributed::Triangulation<dim> *>(
      &triangulation);
  }

  template <int dim>
  const parallel::distributed::Triangulation<dim> *
  as_distributed(const Triangulation<dim> &triangulation)
  {
    return dynamic_cast<const parallel::distributed::Triangulation<dim> *>(
      &triangulation);
  }
} // namespace dyncontact

#endif
