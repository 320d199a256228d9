// A run killed with kill -9 mid-way resumes from its last good checkpoint:
// the dyncontact executable runs a bar impact (160 cells along, 800 steps,
// a checkpoint every 20 steps) and is killed 0.2 s after its first
// checkpoint appeared (not after a fixed time: under load a fixed time could
// fall before the first checkpoint), possibly while it writes a later one;
// resumed with 'Resume = true' it completes, and its statistics.tsv ends
// exactly as an uninterrupted run's (final energy and momentum to 1e-10).
// The folders of an earlier run of the test are removed first.

#include <filesystem>

#include "tests.h"


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace testing;

  auto prm = [](const std::string &dir, const bool resume) {
    return bar_prm(2, "N-CS++", 160, 1. / 320., 2.5) +
           "set Output directory = " + dir + "\n" +
           "subsection Checkpointing\n  set Interval in steps = 20\n" +
           "  set Resume = " + (resume ? "true" : "false") + "\nend\n";
  };
  std::ofstream("killed.prm") << prm("results-killed", false);
  std::ofstream("resumed.prm") << prm("results-killed", true);
  std::ofstream("full.prm") << prm("results-full", false);

  std::filesystem::remove_all("results-killed");
  std::filesystem::remove_all("results-full");
  const std::string exe = DYNCONTACT_EXECUTABLE;
  run_clean("sh -c '" + exe +
            " killed.prm > killed.log 2>&1 & p=$!; i=0; "
            "while [ ! -e results-killed/checkpoints/last ] && "
            "[ $i -lt 2400 ]; do sleep 0.05; i=$((i+1)); done; "
            "sleep 0.2; kill -9 $p; wait $p; true'");
  const bool killed_midway =
    std::filesystem::exists("results-killed/checkpoints/last");
  const std::vector<double> before = last_row("results-killed/statistics.tsv");
  log() << "killed mid-way with a checkpoint written: "
        << check(killed_midway && !before.empty() && before[0] < 800) << "\n";
  std::cout << "killed after step " << (before.empty() ? -1 : before[0])
            << std::endl;

  const std::string resumed = run_clean(exe + " resumed.prm");
  log() << "resumed run completes: "
        << check(resumed.find("command failed") == std::string::npos &&
                 resumed.find("resumed from") != std::string::npos)
        << "\n";
  run_clean(exe + " full.prm");
  const auto a    = last_row("results-full/statistics.tsv");
  const auto b    = last_row("results-killed/statistics.tsv");
  bool       same = a.size() == b.size() && a.size() > 6 && a[0] == 800;
  for (const unsigned int c : {2u, 3u, 5u, 6u, 7u})
    same = same && std::abs(a[c] - b[c]) <= 1e-10 * std::abs(a[c]) + 1e-14;
  log() << "final step, energies and momentum as uninterrupted: " << check(same)
        << "\n";
}
