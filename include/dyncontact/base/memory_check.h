#ifndef dyncontact_base_memory_check_h
#define dyncontact_base_memory_check_h

#include <deal.II/base/mpi.h>

#include <string>

namespace dyncontact
{
  using namespace dealii;

  /// The memory available to a run, and what limits it.
  struct AvailableMemory
  {
    /// bytes, summed over the ranks
    double bytes;
    /// the limit that binds on the rank with the least memory
    std::string limit;
  };

  /**
   * The memory available to this run in bytes, summed over all ranks of
   * @p comm (collective): on each rank the least of its node's
   * MemAvailable (from /proc/meminfo) shared among the ranks on that node,
   * what its address-space limit (ulimit -v) leaves beside its virtual
   * size, and what its control group's memory limit leaves (cgroup v1 or
   * v2, shared among the ranks on the node). Infinite where none can be
   * read.
   */
  AvailableMemory
  available_memory(const MPI_Comm comm);

  /**
   * Stops with a message before a mesh is built that would not fit into
   * memory: @p n_cells active cells (summed over ranks) of dimension @p dim
   * with elements of degree @p degree, of which @p n_coarse_cells are coarse
   * cells (every rank stores the whole coarse mesh). The estimate is a
   * lower bound: per degree of freedom 12 bytes for each of the step
   * matrix's dim (p+2)^dim entries of a row on average (if
   * @p stored_step_matrix: 'Contact solver/Step matrix = assembled'), and
   * 500 bytes of
   * vectors, DoF and mesh data (1.47 kB in 3D for degree 1, where 1.78 kB
   * were measured at 1e6 DoFs), and 2 kB per coarse cell and rank; the message
   * names the estimate, the available memory (available_memory()), what
   * limits it, and @p remedy (the parameters to reduce). For a mesh that
   * grows from @p n_cells_in_use cells (> 0: a mesh the run holds
   * already), what the growth needs is compared. @p what names the mesh
   * in the message. Collective.
   */
  void
  check_mesh_fits_in_memory(const double       n_cells,
                            const int          dim,
                            const unsigned int degree,
                            const bool         stored_step_matrix,
                            const double       n_coarse_cells,
                            const std::string &remedy,
                            const MPI_Comm     comm,
                            const double       n_cells_in_use = 0.,
                            const std::string &what = "the requested mesh");

  /**
   * Hands the memory that the C library keeps after it was freed back to
   * the operating system (glibc's malloc_trim(); nothing with another C
   * library): what a set-up frees in many small blocks, e.g. the rows of a
   * dynamic sparsity pattern or ML's temporaries, would otherwise stay in
   * the resident set (0.5 GB each at 1e6 DoFs in 3D).
   */
  void
  release_freed_memory();
} // namespace dyncontact

#endif
