#ifndef dyncontact_base_collective_errors_h
#define dyncontact_base_collective_errors_h

#include <deal.II/base/mpi.h>

#include <exception>
#include <string>

namespace dyncontact
{
  /**
   * Stops every rank with rank 0's @p message if it is not empty (ignored
   * on the other ranks). Collective: what rank 0 alone does (the statistics
   * file, the summary, the .pvd record, the checkpoint's state) must not
   * stop rank 0 alone, or the others would wait for it in the next
   * collective call.
   */
  void
  stop_with_message_of_rank_0(const std::string &message, const MPI_Comm comm);

  /// Stops every rank with the message of the first rank whose @p message
  /// is not empty (collective; for what each rank does itself).
  void
  stop_with_any_message(const std::string &message, const MPI_Comm comm);

  /// The message of @p e without deal.II's file and line header, trimmed.
  std::string
  message_of(const std::exception &e);

  /// "Cannot write '<file>': <the system's reason>." (from errno), for a
  /// stream that failed.
  std::string
  write_failure(const std::string &file);
} // namespace dyncontact

#endif
