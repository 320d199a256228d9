#ifndef dyncontact_output_output_directory_h
#define dyncontact_output_output_directory_h

#include <deal.II/base/mpi.h>

#include <string>

namespace dyncontact
{
  /**
   * The output directory of a run: created if needed, checked to be
   * writable, and locked for the run's lifetime by the file ".lock" in it
   * (host name and process id of rank 0), so that two runs cannot write
   * into one directory at the same time. A lock left by a run that no longer
   * lives (killed, on this host) is replaced with a note. The lock is
   * removed when this object is destroyed (also when the run fails).
   * Nothing else in the directory is touched. Collective; throws with a
   * message naming the directory.
   */
  class OutputDirectory
  {
  public:
    OutputDirectory(const std::string &directory, const MPI_Comm comm);

    ~OutputDirectory();

    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &
    operator=(const OutputDirectory &) = delete;

  private:
    std::string lock_file;
    bool        owns_lock = false;
  };
} // namespace dyncontact

#endif
