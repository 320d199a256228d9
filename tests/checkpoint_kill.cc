// A run killed with kill -9 mid-way resumes from its last good checkpoint:
// the dyncontact executable runs a bar impact (160 cells along, 640 steps,
// a checkpoint every 20 steps) and is killed 0.1 s after its first
// checkpoint appeared (not after a fixed time: under load a fixed time could
// fall before the first checkpoint), possibly while it writes a later one;
// resumed with 'Resume = true' it completes, and its statistics.tsv ends
// exactly as an uninterrupted run's (final energy and momentum to 1e-10).
// The folders of an earlier run of the test are removed first.
//
// A run on 2 ranks whose mpirun (and its process group) is killed with
// kill -9 leaves no rank running: Open MPI gives each rank a process group
// of its own, and without the program's own care they ran on for about a
// second. Both ranks must be gone (or zombies) within 0.5 s.

#include <signal.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "tests.h"


namespace
{
  /// The processes whose parent is @p parent (from /proc).
  std::vector<int>
  children_of(const int parent)
  {
    std::vector<int> children;
    for (const auto &entry : std::filesystem::directory_iterator("/proc"))
      {
        std::ifstream stat(entry.path() / "stat");
        std::string   line;
        if (!std::getline(stat, line) || line.rfind(')') == std::string::npos)
          continue;
        // pid (comm) state ppid ...: comm may hold blanks
        std::istringstream rest(line.substr(line.rfind(')') + 1));
        char               state;
        int                ppid;
        if (rest >> state >> ppid && ppid == parent)
          children.push_back(std::stoi(entry.path().filename()));
      }
    return children;
  }

  /// Whether @p pid runs (exists and is no zombie).
  bool
  is_running(const int pid)
  {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string   line;
    if (!std::getline(stat, line) || line.rfind(')') == std::string::npos)
      return false;
    std::istringstream rest(line.substr(line.rfind(')') + 1));
    char               state = 'Z';
    rest >> state;
    return state != 'Z' && state != 'X';
  }
} // namespace



int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  auto prm = [](const std::string &dir, const bool resume) {
    return bar_prm(2, "N-CS++", 160, 1. / 320., 2.) +
           "set Output directory = " + dir + "\n" +
           "subsection Checkpointing\n  set Interval in steps = 20\n" +
           "  set Resume = " + (resume ? "true" : "false") + "\nend\n" +
           // (the error norm is not compared: at the output times)
           "subsection Postprocess\n  subsection Error energy norm\n"
           "    set Interval = output times\n  end\nend\n";
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
            "sleep 0.1; kill -9 $p; wait $p; true'");
  const bool killed_midway =
    std::filesystem::exists("results-killed/checkpoints/last");
  const std::vector<double> before = last_row("results-killed/statistics.tsv");
  log() << "killed mid-way with a checkpoint written: "
        << check(killed_midway && !before.empty() && before[0] < 640) << "\n";
  std::cout << "killed after step " << (before.empty() ? -1 : before[0])
            << std::endl;

  const std::string resumed = run_clean(exe + " resumed.prm");
  log() << "resumed run completes: "
        << check(resumed.find("command failed") == std::string::npos &&
                 resumed.find("resumed from") != std::string::npos)
        << "\n";
  run_clean(exe + " full.prm");
  const Statistics a = read_statistics("results-full/statistics.tsv");
  const Statistics b = read_statistics("results-killed/statistics.tsv");
  bool same = a.columns == b.columns && !a.rows.empty() && !b.rows.empty() &&
              a.column("step").back() == 640 && b.column("step").back() == 640;
  for (const std::string name : {"energy_kinetic",
                                 "energy_elastic",
                                 "energy_total",
                                 "energy_balance",
                                 "momentum_x"})
    if (same)
      {
        const double x = a.column(name).back(), y = b.column(name).back();
        same = std::abs(x - y) <= 1e-10 * std::abs(x) + 1e-14;
      }
  log() << "final step, energies and momentum as uninterrupted: " << check(same)
        << "\n";

  // the ranks of a killed mpirun
  std::ofstream("ranks.prm") << bar_prm(2, "N-CS++", 160, 1. / 320., 1000.) +
                                  "set Output directory = results-ranks\n" +
                                  "subsection Checkpointing\n"
                                  "  set Interval in steps = 20\nend\n";
  std::filesystem::remove_all("results-ranks");
  std::filesystem::remove("mpirun.pid");
  run_clean("sh -c 'setsid " + std::string(DYNCONTACT_MPIEXEC) + " -np 2 " +
            exe + " ranks.prm > ranks.log 2>&1 & echo $! > mpirun.pid'");
  int launcher = 0;
  std::ifstream("mpirun.pid") >> launcher;
  std::vector<int> ranks;
  for (unsigned int i = 0; i < 2400 && launcher > 0; ++i)
    {
      ranks = children_of(launcher);
      if (ranks.size() == 2 &&
          std::filesystem::exists("results-ranks/checkpoints/last"))
        break;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  const bool started = launcher > 0 && ranks.size() == 2;
  if (launcher > 0)
    kill(-launcher, SIGKILL);
  const auto killed  = std::chrono::steady_clock::now();
  bool       running = true;
  while (running &&
         std::chrono::steady_clock::now() - killed < std::chrono::seconds(5))
    {
      running = false;
      for (const int rank : ranks)
        running = running || is_running(rank);
      if (running)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - killed)
      .count();
  for (const int rank : ranks)
    if (is_running(rank))
      kill(rank, SIGKILL);
  log() << "the 2 ranks of a killed mpirun end within 0.5 s: "
        << check(started && !running && seconds < 0.5) << "\n";
  std::cout << "ranks ended " << seconds << " s after the kill" << std::endl;
}
