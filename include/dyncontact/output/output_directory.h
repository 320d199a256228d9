#ifndef dyncontact_output_output_directory_h
#define dyncontact_output_output_directory_h

#include <deal.II/base/mpi.h>

#include <string>

namespace dyncontact
{
  /// Creates the output directory if needed and checks that it can be
  /// written (collective); nothing in it is touched. Throws with a message
  /// naming the directory otherwise.
  void
  prepare_output_directory(const std::string &directory, const MPI_Comm comm);
} // namespace dyncontact

#endif
