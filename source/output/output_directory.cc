#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <dyncontact/output/output_directory.h>

#include <filesystem>
#include <fstream>

namespace dyncontact
{
  using namespace dealii;

  void
  prepare_output_directory(const std::string &directory, const MPI_Comm comm)
  {
    bool writable = true;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(directory, error);
        const std::string probe = directory + "/.dyncontact-write-test";
        writable                = std::ofstream(probe).good();
        std::filesystem::remove(probe, error);
      }
    writable = Utilities::MPI::broadcast(comm, writable, 0);
    AssertThrow(writable,
                ExcMessage("Output directory '" + directory +
                           "' cannot be created or written."));
  }
} // namespace dyncontact
