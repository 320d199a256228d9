#ifndef dyncontact_contact_contact_search_h
#define dyncontact_contact_contact_search_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dyncontact/contact/contact_mapping.h>

#include <algorithm>
#include <vector>

namespace dyncontact
{
  using namespace dealii;

  /**
   * The parallel contact search: of the faces that all ranks pass in
   * @p faces (each its own), those whose bounding box meets the box of
   * half-width @p radius around one of this rank's @p points, in rank
   * order. Every rank sends its points only to the ranks whose faces'
   * bounding box they meet, and gets back only the faces near them; the
   * only global communication is one bounding box per rank. Collective.
   */
  template <int dim>
  std::vector<MasterFace<dim>>
  faces_near(const std::vector<MasterFace<dim>> &faces,
             const std::vector<Point<dim>>      &points,
             const double                        radius,
             const MPI_Comm                      comm);



  /**
   * The closest-point search at any distance: of the faces that all ranks of
   * @p comm pass in @p faces (each its own), those on which the closest
   * point of one of this rank's @p points may lie (every face whose bounding
   * box is as near as the least distance, up to round-off), in rank order,
   * so that ContactMapping::find_closest() on them finds what it would find
   * on the whole surface. The ranks exchange one bounding box each; a point
   * goes only to the ranks whose box is no farther than the least
   * MINMAXDIST of the boxes (a face of that rank lies that near), which
   * answer first with their least distance, then with their faces at the
   * least distance over all ranks. Collective.
   */
  template <int dim>
  std::vector<MasterFace<dim>>
  closest_faces(const std::vector<MasterFace<dim>> &faces,
                const std::vector<Point<dim>>      &points,
                const MPI_Comm                      comm);



  /// Moves the vertices and the cell centre of each of @p faces by the
  /// displacement @p ghosted (its vertex DoFs locally relevant): the
  /// deformed surface.
  template <int dim, typename Vector>
  void
  deform(std::vector<MasterFace<dim>> &faces, const Vector &ghosted)
  {
    for (auto &face : faces)
      {
        Tensor<1, dim> mean;
        for (unsigned int v = 0; v < face.vertices.size(); ++v)
          {
            Tensor<1, dim> displacement;
            for (unsigned int d = 0; d < dim; ++d)
              displacement[d] = ghosted(face.vertex_dofs[v * dim + d]);
            face.vertices[v] += displacement;
            mean += displacement / double(face.vertices.size());
          }
        face.cell_center += mean;
      }
  }



  /**
   * The largest of the ranks' @p depth, and the @p data of the rank that
   * has it (the first among equals), on every rank: for the deepest of
   * the points that each rank found. Collective.
   */
  inline void
  deepest_over_ranks(double &depth, std::vector<double> &data, MPI_Comm comm)
  {
    const double       largest = Utilities::MPI::max(depth, comm);
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int owner   = Utilities::MPI::min(
      depth == largest ? my_rank : Utilities::MPI::n_mpi_processes(comm), comm);
    if (owner != my_rank)
      std::fill(data.begin(), data.end(), 0.);
    Utilities::MPI::sum(data, comm, data);
    depth = largest;
  }
} // namespace dyncontact

#endif
