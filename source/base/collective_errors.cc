#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <dyncontact/base/collective_errors.h>

#include <cerrno>
#include <cstring>
#include <new>
#include <sstream>

namespace dyncontact
{
  void
  stop_with_message_of_rank_0(const std::string &message, const MPI_Comm comm)
  {
    const std::string text =
      dealii::Utilities::MPI::broadcast(comm, message, 0);
    AssertThrow(text.empty(), dealii::ExcMessage(text));
  }



  void
  stop_with_any_message(const std::string &message, const MPI_Comm comm)
  {
    for (const std::string &text :
         dealii::Utilities::MPI::all_gather(comm, message))
      AssertThrow(text.empty(), dealii::ExcMessage(text));
  }



  std::string
  message_of(const std::exception &e)
  {
    std::ostringstream s;
    if (const auto *dealii_exception =
          dynamic_cast<const dealii::ExceptionBase *>(&e))
      dealii_exception->print_info(s);
    else if (dynamic_cast<const std::bad_alloc *>(&e) != nullptr)
      // (past the memory checks before each mesh: e.g. a solver's or a
      // library's own allocations)
      s << "the run ran out of memory (" << e.what()
        << "): it needed more than the memory available to it, the least "
           "of the machine's, the process's address-space limit (ulimit -v) "
           "and its control group's (a batch system's) limit. Reduce the "
           "mesh (Mesh/Initial global refinements, Mesh refinement/Maximum "
           "level) or the Polynomial degree, take 'Contact solver/Step "
           "matrix = matrix-free', or run on more MPI ranks or nodes.";
    else
      s << e.what();
    const std::string text = s.str();
    // trim leading and trailing white space
    const auto first = text.find_first_not_of(" \n\t");
    const auto last  = text.find_last_not_of(" \n\t");
    return first == std::string::npos ? std::string("unknown error") :
                                        text.substr(first, last - first + 1);
  }



  std::string
  write_failure(const std::string &file)
  {
    const int error = errno;
    return "Cannot write '" + file + "'" +
           (error != 0 ? std::string(": ") + std::strerror(error) : "") + ".";
  }
} // namespace dyncontact
