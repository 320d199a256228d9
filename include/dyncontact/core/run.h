#ifndef dyncontact_run_h
#define dyncontact_run_h

#include <dyncontact/base/statistics.h>

#include <mpi.h>

#include <iosfwd>
#include <memory>
#include <string>

namespace dealii::Utilities::MPI
{
  class MPI_InitFinalize;
}

namespace dyncontact
{
  /**
   * Runs the simulation described by the parameter text @p prm_text (the
   * contents of a .prm file) and returns the per-step statistics, the same
   * on every rank. @p source names the text in error messages.
   */
  Statistics
  run_simulation(const std::string &prm_text,
                 const MPI_Comm     comm,
                 const std::string &source = "<input>");

  /// Prints every parameter with documentation, units and default.
  void
  print_parameters(std::ostream &out);

  /// The program: dyncontact [--help] file.prm. Returns the exit status.
  int
  main_program(int argc, char **argv);

  /// The program once MPI runs (main_program() starts MPI, then calls
  /// this): the help, or the run of the parameter file argv[1] on
  /// MPI_COMM_WORLD, with "dyncontact: error: ..." on std::cerr if it
  /// fails. Returns the exit status. (The tests call it in their own
  /// process, for the many inputs that must be refused.)
  int
  run_command_line(int argc, char **argv);

  /**
   * deal.II's Utilities::MPI::MPI_InitFinalize with one thread (MPI, p4est,
   * PETSc and what else deal.II starts with MPI, for the life of the
   * object) behind a header that includes none of deal.II: the tests that
   * drive the program through run_simulation() compile in a second instead
   * of parsing deal.II.
   */
  class MPIInitFinalize
  {
  public:
    MPIInitFinalize(int &argc, char **&argv);
    ~MPIInitFinalize();

  private:
    std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  };
} // namespace dyncontact

#endif
