// The VTU/PVTU/PVD output opens in ParaView: a bar impact written by the
// dyncontact executable on one and on two MPI ranks, and on two ranks in
// several pieces per rank ('Cells per piece'), is loaded with pvpython
// (tests/check_vtu.py), which checks that all fields are there and that the
// mesh warped by the displacement puts the bar's end where the exact
// solution puts it (free flight, in contact at the wall, after release),
// and that the velocity, von Mises stress, contact pressure and critical
// set fields are the exact ones in free flight and behind and ahead of the
// compression front (the stress rho c v0).
// Then 2-rank runs whose ranks write different numbers of pieces, or none
// (tests/check_pieces.py: every listed piece exists, all cells are there),
// and a two-bars run (tests/check_two_bodies.py): the gap field on the
// slave face and the contact pressure on both sides.

#include "tests.h"


/// The number of pieces a .pvtu record lists.
unsigned int
count_pieces(const std::string &pvtu)
{
  std::ifstream in(pvtu);
  std::string   line;
  unsigned int  n = 0;
  while (std::getline(in, line))
    n += (line.find("<Piece Source=") != std::string::npos);
  return n;
}



int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  // the ParaView checks of all runs, in one pvpython at the end (each start
  // of pvpython takes seconds)
  std::string checks;
  const auto  add_check = [&](const std::string &script,
                             const std::string &directory) {
    checks += std::string(checks.empty() ? "" : " --next ") + SOURCE_DIR + "/" +
              script + " " + directory;
  };

  // (ranks, cells per VTU piece): one piece per rank, then 3 pieces of at
  // most 30 of the 80 cells on each of 2 ranks
  for (const auto &[n_ranks, cells_per_piece] :
       std::vector<std::pair<unsigned int, unsigned int>>{{1, 65536},
                                                          {2, 65536},
                                                          {2, 30}})
    {
      const std::string directory = "results-" + std::to_string(n_ranks) + "-" +
                                    std::to_string(cells_per_piece);
      std::ofstream(directory + ".prm")
        << bar_prm(2, "N-CS++", 40, 0.0125, 2.5)
        << "set Output directory = " << directory << "\n"
        << "subsection Output\n  set Write vtu = true\n"
        << "  set Output interval = 0.05\n"
        << "  set Cells per piece = " << cells_per_piece << "\nend\n";
      const std::string program =
        n_ranks == 1 ?
          std::string(DYNCONTACT_EXECUTABLE) :
          std::string(DYNCONTACT_MPIEXEC) + " -np 2 " + DYNCONTACT_EXECUTABLE;
      const std::string run_output =
        run_clean(program + " " + directory + ".prm");
      log() << n_ranks << " rank(s), at most " << cells_per_piece
            << " cells per piece: run "
            << check(run_output.find("command failed") == std::string::npos)
            << ", pieces in the last record: "
            << count_pieces(directory + "/solution_00050.pvtu") << "\n";
      add_check("check_vtu.py", directory);
    }

  // ranks with different numbers of pieces (3 cells on 2 ranks, one cell
  // per piece), and a rank without cells (1 cell on 2 ranks): each rank
  // takes part in the collective rounds of the others' pieces
  for (const unsigned int n_cells : {3u, 1u})
    {
      const std::string directory = "results-uneven-" + std::to_string(n_cells);
      std::ofstream(directory + ".prm")
        << bar_prm(2, "N-CS++", n_cells, 0.0125, 0.1)
        << "set Output directory = " << directory << "\n"
        << "subsection Output\n  set Write vtu = true\n"
        << "  set Output interval = 0.05\n  set Cells per piece = 1\nend\n";
      log() << n_cells << " cell(s) on 2 ranks, 1 cell per piece: run "
            << check(run_clean(std::string(DYNCONTACT_MPIEXEC) + " -np 2 " +
                               DYNCONTACT_EXECUTABLE + " " + directory + ".prm")
                       .find("command failed") == std::string::npos)
            << "\n";
      add_check("check_pieces.py", directory);
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
  add_check("check_two_bodies.py", "results-two-bars");
  log() << "ParaView:\n"
        << run_clean(std::string(DYNCONTACT_PVPYTHON) + " " + SOURCE_DIR +
                     "/run_checks.py " + checks);
}
