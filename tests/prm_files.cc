// Every example in prm/ is a valid input: each is parsed and set up (mesh,
// matrices, contact rows, initial step) with the end time set to zero (and
// the static examples run as dynamic ones, so that nothing is solved).

#include <filesystem>
#include <set>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  std::set<std::filesystem::path> files;
  for (const auto &entry :
       std::filesystem::directory_iterator(DYNCONTACT_PRM_DIR))
    if (entry.path().extension() == ".prm")
      files.insert(entry.path());

  for (const auto &file : files)
    {
      std::ifstream     in(file);
      std::stringstream text;
      text << in.rdbuf() << "\nset Output directory = results-"
           << file.stem().string()
           << "\nsubsection Time integration\n  set End time = 0\n"
           << "  set Scheme = N-CS++\nend\n"
           << "subsection Output\n  set Write vtu = false\nend\n";
      const Statistics s =
        dyncontact::run_simulation(text.str(), MPI_COMM_WORLD, file.string());
      log() << file.filename().string() << ": parsed and set up, "
            << check(s.rows.size() == 1) << ", energy "
            << fmt(s.column("energy_total")[0], 3) << "\n";
    }
}
