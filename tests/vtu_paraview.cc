// The VTU/PVTU/PVD output opens in ParaView: a bar impact written by the
// dyncontact executable on one and on two MPI ranks is loaded with pvpython
// (tests/check_vtu.py), which checks that all fields are there and that the
// mesh warped by the displacement puts the bar's end where the exact
// solution puts it (free flight, in contact at the wall, after release).
// Then a two-bars run (tests/check_two_bodies.py): the gap field on the
// slave face and the contact pressure on both sides.

#include "tests.h"


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace testing;

  for (const unsigned int n_ranks : {1u, 2u})
    {
      const std::string directory = "results-" + std::to_string(n_ranks);
      std::ofstream(directory + ".prm")
        << bar_prm(2, "N-CS++", 40, 0.0125, 2.5)
        << "set Output directory = " << directory << "\n"
        << "subsection Output\n  set Write vtu = true\n"
        << "  set Output interval = 0.05\nend\n";
      const std::string program =
        n_ranks == 1 ?
          std::string(DYNCONTACT_EXECUTABLE) :
          std::string(DYNCONTACT_MPIEXEC) + " -np 2 " + DYNCONTACT_EXECUTABLE;
      const std::string run_output =
        run_clean(program + " " + directory + ".prm");
      log() << n_ranks << " rank(s): run "
            << check(run_output.find("command failed") == std::string::npos)
            << "\n";
      log() << run_clean(std::string(DYNCONTACT_PVPYTHON) + " " + SOURCE_DIR +
                         "/check_vtu.py " + directory);
    }

  std::ofstream("two-bars.prm")
    << bar_prm(2, "N-CS++", 40, 0.0125, 1.2)
    << "set Output directory = results-two-bars\n"
    << scene_prm("two bars")
    << "subsection Contact\n  set Slave side = 2\nend\n"
    << "subsection Output\n  set Write vtu = true\n"
    << "  set Output interval = 0.1\nend\n";
  log() << "two bars: run "
        << check(run_clean(std::string(DYNCONTACT_EXECUTABLE) + " two-bars.prm")
                   .find("command failed") == std::string::npos)
        << "\n";
  log() << run_clean(std::string(DYNCONTACT_PVPYTHON) + " " + SOURCE_DIR +
                     "/check_two_bodies.py results-two-bars");
}
