// Every file the program writes is checked: a write that fails stops the
// run with "dyncontact: error:" and a message naming the file, a non-zero
// exit status and no backtrace (a second review of the trust in the results).
// The files are made unwritable as root can (a directory in the file's place,
// or the file a link to /dev/full, where every write fails with "No space left
// on device"): statistics.tsv when it is opened and when a row is added,
// summary.txt, the .pvd record of the VTU files, a checkpoint's mark.
// Earlier, each of these runs ended with exit status 0.

#include <filesystem>

#include "tests.h"

namespace
{
  namespace fs = std::filesystem;

  const std::string prm = "set Dimension = 2\n"
                          "set Output directory = out\n"
                          "subsection Time integration\n"
                          "  set End time = 0.05\n"
                          "end\n";
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  struct Case
  {
    std::string name, file, extra;
    bool        to_dev_full;
  };
  const std::string no_vtu =
    "subsection Output\n  set Write vtu = false\nend\n";
  for (const Case &c :
       {Case{"statistics.tsv is a directory", "statistics.tsv", no_vtu, false},
        Case{"statistics.tsv on a full disk", "statistics.tsv", no_vtu, true},
        Case{"summary.txt is a directory", "summary.txt", no_vtu, false},
        Case{"summary.txt on a full disk", "summary.txt", no_vtu, true},
        Case{"solution.pvd is a directory", "solution.pvd", "", false},
        Case{"a checkpoint's mark is a directory",
             "checkpoints/last.tmp",
             no_vtu + "subsection Checkpointing\n"
                      "  set Interval in steps = 2\nend\n",
             false}})
    {
      fs::remove_all("out");
      fs::create_directories(fs::path("out") / c.file);
      if (c.to_dev_full)
        {
          fs::remove(fs::path("out") / c.file);
          fs::create_symlink("/dev/full", fs::path("out") / c.file);
        }
      std::ofstream("case.prm") << prm << c.extra;
      const Outcome outcome = run_program("case.prm");
      const bool    named   = error_names(outcome, c.file);
      const bool    clean   = without_backtrace(outcome);
      log() << c.name
            << ": exit status non-zero: " << check(outcome.status != 0)
            << ", message names '" << c.file << "': " << check(named)
            << ", no backtrace: " << check(clean) << "\n";
      if (outcome.status == 0 || !named || !clean)
        std::cout << c.name << ":\n" << outcome.text << std::endl;
    }
  fs::remove_all("out");
}
