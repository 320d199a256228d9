#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/base/memory_check.h>

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

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



  namespace
  {
    /// The first number in file @p name (nan if none).
    double
    number_in(const std::string &name)
    {
      std::ifstream in(name);
      double        value = std::nan("");
      in >> value;
      return in ? value : std::nan("");
    }

    /// The value of @p key in a file of "key value" lines (0 if none).
    double
    value_in(const std::string &name, const std::string &key)
    {
      std::ifstream in(name);
      for (std::string k; in >> k;)
        {
          double value = 0.;
          in >> value;
          if (k == key && in)
            return value;
        }
      return 0.;
    }

    /// The memory its cgroup still allows this process (bytes): the least
    /// of limit - usage over the cgroup and its ancestors, for cgroup v2
    /// (memory.max, memory.current) and v1 (memory.limit_in_bytes,
    /// memory.usage_in_bytes); infinite without a limit.
    double
    cgroup_headroom()
    {
      double        headroom = std::numeric_limits<double>::infinity();
      std::ifstream cgroups("/proc/self/cgroup");
      for (std::string line; std::getline(cgroups, line);)
        {
          // "0::/path" (v2) or "4:memory:/path" (v1)
          const auto first  = line.find(':');
          const auto second = line.find(':', first + 1);
          if (first == std::string::npos || second == std::string::npos)
            continue;
          const std::string controllers =
            line.substr(first + 1, second - first - 1);
          const std::string path = line.substr(second + 1);
          std::vector<std::pair<std::string, std::string>> files;
          if (controllers.empty())
            files = {{"/sys/fs/cgroup", "memory.max"},
                     {"/sys/fs/cgroup/unified", "memory.max"}};
          else if (("," + controllers + ",").find(",memory,") !=
                   std::string::npos)
            files = {{"/sys/fs/cgroup/memory", "memory.limit_in_bytes"}};
          for (const auto &[root, limit_file] : files)
            // the cgroup and its ancestors (a container may see its own
            // cgroup as the root)
            for (std::string p = path;;)
              {
                const std::string folder = root + (p == "/" ? "" : p);
                const double      limit  = number_in(folder + "/" + limit_file);
                const double      usage  = number_in(folder + "/" +
                                               (limit_file == "memory.max" ?
                                                        "memory.current" :
                                                        "memory.usage_in_bytes"));
                // ("max", or about 2^63 in v1: no limit); the inactive
                // file cache counts as usage but is given back on demand
                if (std::isfinite(limit) && std::isfinite(usage) &&
                    limit < 1e18)
                  headroom =
                    std::min(headroom,
                             std::max(0.,
                                      limit - usage +
                                        value_in(folder + "/memory.stat",
                                                 limit_file == "memory.max" ?
                                                   "inactive_file" :
                                                   "total_inactive_file")));
                if (p.empty() || p == "/")
                  break;
                const auto slash = p.rfind('/');
                p                = slash == 0 || slash == std::string::npos ?
                                     "/" :
                                     p.substr(0, slash);
              }
        }
      return headroom;
    }

    /// What the address-space limit (ulimit -v, RLIMIT_AS) still allows
    /// this process (bytes): the limit less its virtual size now; infinite
    /// without a limit.
    double
    address_space_headroom()
    {
      rlimit limit;
      if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
        return std::numeric_limits<double>::infinity();
      double        size = 0.;
      std::ifstream status("/proc/self/status");
      for (std::string key; status >> key;)
        {
          if (key == "VmSize:")
            {
              status >> size;
              size *= 1024.;
              break;
            }
          status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
        }
      return std::max(0., double(limit.rlim_cur) - size);
    }
  } // namespace



  AvailableMemory
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
    // the least of the three on this rank, and which one it is
    const std::array<double, 3> limits = {{bytes / ranks_on_node,
                                           address_space_headroom(),
                                           cgroup_headroom() / ranks_on_node}};
    const auto least = std::min_element(limits.begin(), limits.end());
    const auto sum   = Utilities::MPI::sum(*least, comm);
    // the binding limit of the rank with the least memory
    const auto   min = Utilities::MPI::min_max_avg(*least, comm);
    unsigned int kind =
      min.min_index == Utilities::MPI::this_mpi_process(comm) ?
        least - limits.begin() :
        0;
    kind = Utilities::MPI::broadcast(comm, kind, min.min_index);
    static const char *const names[] = {
      "the machine's available memory",
      "the process's address-space limit (ulimit -v)",
      "the memory limit of the process's control group (cgroup)"};
    return {sum, names[kind]};
  }



  void
  check_mesh_fits_in_memory(const double       n_cells,
                            const int          dim,
                            const unsigned int degree,
                            const bool         stored_step_matrix,
                            const double       n_coarse_cells,
                            const std::string &remedy,
                            const MPI_Comm     comm,
                            const double       n_cells_in_use,
                            const std::string &what)
  {
    const double dofs_per_cell = dim * std::pow(double(degree), dim);
    const double n_ranks       = Utilities::MPI::n_mpi_processes(comm);
    // a lower bound per DoF: the step matrix's values and column indices
    // (12 bytes for each of dim (p+2)^dim entries of a row on average) and
    // 500 bytes of vectors, DoF and mesh data (3D, degree 1, at 1e6 DoFs:
    // 1.47 kB against 1.78 kB measured, libraries apart)
    const double bytes_per_dof =
      (stored_step_matrix ? 12. * dim * std::pow(degree + 2., dim) : 0.) + 500.;
    // (a mesh in use holds its memory already: what its growth needs)
    const double estimate =
      bytes_per_dof * dofs_per_cell * (n_cells - n_cells_in_use) +
      (n_cells_in_use > 0. ? 0. : 2e3 * n_coarse_cells * n_ranks);
    if (estimate <= 0.)
      return;
    const AvailableMemory available = available_memory(comm);
    if (estimate <= available.bytes)
      return;
    std::ostringstream message;
    message << std::setprecision(3) << what << " would have about " << n_cells
            << " cells (" << dofs_per_cell * n_cells
            << " unknowns) and need at least about " << estimate / 1e9
            << (n_cells_in_use > 0. ? " GB more memory than the mesh in use" :
                                      " GB of memory")
            << ", more than the " << available.bytes / 1e9
            << " GB available to this run (summed over its " << n_ranks
            << " MPI rank(s); the limit is " << available.limit << "). Reduce "
            << remedy << ".";
    AssertThrow(false, ExcMessage(message.str()));
  }
} // namespace dyncontact
