#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dyncontact/base/collective_errors.h>
#include <dyncontact/core/parameter_file.h>
#include <dyncontact/core/run.h>
#include <dyncontact/core/simulator.h>

#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace dyncontact
{
  Statistics
  run_simulation(const std::string &prm_text,
                 const MPI_Comm     comm,
                 const std::string &source)
  {
    std::vector<std::string> origins;
    const std::string        text = expand_includes(prm_text, source, origins);
    const auto       set_entries  = check_for_misplaced_entries(text, origins);
    ParameterHandler prm;
    declare_all_parameters(prm);
    std::istringstream in(text);
    try
      {
        prm.parse_input(in, source);
      }
    catch (const ExceptionBase &e)
      {
        // the line in the file the user wrote, not in the expanded text
        AssertThrow(false,
                    ExcMessage(with_origin(message_of(e), source, origins)));
      }

    std::string input_directory;
    if (std::filesystem::exists(source))
      input_directory = std::filesystem::path(source).parent_path().string();

    GlobalParameters global;
    global.parse_parameters(prm);
    if (global.dimension == 2)
      return Simulator<2>(prm, input_directory, comm, set_entries).run();
    else
      return Simulator<3>(prm, input_directory, comm, set_entries).run();
  }



  void
  print_parameters(std::ostream &out)
  {
    ParameterHandler prm;
    declare_all_parameters(prm);
    prm.print_parameters(out, ParameterHandler::PRM);
  }



  namespace
  {
    /**
     * A rank that mpirun started dies with it: Open MPI puts each rank in a
     * process group of its own, so that a kill -9 of mpirun (or of its
     * process group) leaves the ranks running until they miss it, about a
     * second later, long enough to write a step's files after the run was
     * killed. Linux sends them SIGKILL when their parent, mpirun, ends. (A
     * rank whose parent ended while this was set has been given to another
     * process: it ends itself.)
     */
    void
    die_with_mpirun()
    {
      if (std::getenv("OMPI_COMM_WORLD_RANK") == nullptr)
        return;
      const pid_t launcher = getppid();
      if (prctl(PR_SET_PDEATHSIG, SIGKILL) == 0 && getppid() != launcher)
        std::_Exit(1);
    }
  } // namespace



  int
  main_program(int argc, char **argv)
  {
    die_with_mpirun();
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    return run_command_line(argc, argv);
  }



  MPIInitFinalize::MPIInitFinalize(int &argc, char **&argv)
    : mpi(std::make_unique<Utilities::MPI::MPI_InitFinalize>(argc, argv, 1))
  {}



  MPIInitFinalize::~MPIInitFinalize() = default;



  int
  run_command_line(int argc, char **argv)
  {
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const std::string usage =
      "Usage: dyncontact [--help] input.prm\n"
      "Runs the simulation described by input.prm. Without an argument, or "
      "with --help,\nprints every parameter with its documentation, units "
      "and default.\n";

    try
      {
        if (argc < 2 || std::string(argv[1]) == "--help" ||
            std::string(argv[1]) == "-h")
          {
            if (root)
              {
                std::cout << usage << '\n';
                print_parameters(std::cout);
              }
            return 0;
          }
        AssertThrow(argc == 2,
                    ExcMessage("expected exactly one argument, the parameter "
                               "file.\n" +
                               usage));

        const std::string filename = argv[1];
        AssertThrow(std::filesystem::exists(filename),
                    ExcMessage("the parameter file '" + filename +
                               "' does not exist."));
        AssertThrow(std::filesystem::is_regular_file(filename),
                    ExcMessage("the parameter file '" + filename +
                               "' is not a regular file."));
        std::ifstream file(filename);
        AssertThrow(file.good(),
                    ExcMessage("cannot open the parameter file '" + filename +
                               "' for reading."));
        std::stringstream text;
        text << file.rdbuf();

        run_simulation(text.str(), MPI_COMM_WORLD, filename);
      }
    catch (const std::exception &e)
      {
        if (root)
          std::cerr << "\ndyncontact: error: " << message_of(e) << "\n"
                    << std::endl;
        return 1;
      }
    return 0;
  }
} // namespace dyncontact
