#ifndef dyncontact_output_output_directory_h
#define dyncontact_output_output_directory_h

#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

namespace dyncontact
{
  /**
   * The output directory of a run: created if needed, checked to be
   * writable, and locked for the run's lifetime by the file ".lock" in it
   * (host name and process id of rank 0), so that two runs cannot write
   * into one directory at the same time. A lock left by a run that no longer
   * lives (killed, on this host) is replaced with a note. The lock is
   * removed when this object is destroyed (also when the run fails).
   * Before the lock is taken, each of @p files (names in the directory that
   * the run writes) and the lock file itself must be a regular file with
   * no other name, or absent: a symbolic or hard link, FIFO, device or
   * directory in their place is refused with a message naming it (a run
   * must not write through a link into another file, nor block on opening
   * a FIFO); a name ending in '/' is a folder of the run's (a directory,
   * or a link to one, or absent).
   * Nothing else in the directory is touched. Collective; throws with a
   * message naming the directory.
   */
  class OutputDirectory
  {
  public:
    OutputDirectory(const std::string              &directory,
                    const std::vector<std::string> &files,
                    const MPI_Comm                  comm);

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
