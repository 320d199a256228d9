#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/memory_check.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#ifdef __GLIBC__
#  include <malloc.h>
#endif

namespace dyncontact
{
  void
  release_freed_memory()
  {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
  }



  double
  available_memory(const MPI_Comm comm)
  {
    // this node's available memory, shared among its ranks
    double        bytes = std::numeric_limits<double>::infinity();
    std::ifstream meminfo("/proc/meminfo");
    for (std::string key; meminfo >> key;)
      {
        double kilobytes = 0.;
        meminfo >> kilobytes;
        if (key == "MemAvailable:" && meminfo)
          {
            bytes = 1024. * kilobytes;
            break;
          }
        meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      }
    MPI_Comm node;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    const unsigned int ranks_on_node = Utilities::MPI::n_mpi_processes(node);
    MPI_Comm_free(&node);
    return Utilities::MPI::sum(bytes / ranks_on_node, comm);
  }



  void
  check_mesh_fits_in_memory(const double       n_cells,
                            const int          dim,
                            const unsigned int degree,
                            const bool         stored_step_matrix,
                            const double       n_coarse_cells,
                            const std::string &remedy,
                            const MPI_Comm     comm)
  {
    const double dofs_per_cell = dim * std::pow(double(degree), dim);
    const double n_ranks       = Utilities::MPI::n_mpi_processes(comm);
    // a lower bound per DoF: the step matrix's values and column indices
    // (12 bytes for each of dim (p+2)^dim entries of a row on average) and
    // 500 bytes of vectors, DoF and mesh data (3D, degree 1, at 1e6 DoFs:
    // 1.47 kB against 1.78 kB measured, libraries apart)
    const double bytes_per_dof =
      (stored_step_matrix ? 12. * dim * std::pow(degree + 2., dim) : 0.) + 500.;
    const double estimate =
      bytes_per_dof * dofs_per_cell * n_cells + 2e3 * n_coarse_cells * n_ranks;
    const double available = available_memory(comm);
    if (estimate <= available)
      return;
    std::ostringstream message;
    message << std::setprecision(3) << "the requested mesh would have about "
            << n_cells << " cells (" << dofs_per_cell * n_cells
            << " unknowns) and need at least about " << estimate / 1e9
            << " GB of memory, more than the " << available / 1e9
            << " GB available to this run (summed over its " << n_ranks
            << " MPI rank(s)). Reduce " << remedy << ".";
    AssertThrow(false, ExcMessage(message.str()));
  }
} // namespace dyncontact
