// The output directory holds one run's files: a run into the directory of an
// earlier, longer run removes the earlier run's solution_* files from the
// first number it writes on (those it does not overwrite would sit beside its
// own, and a file browser or a glob would mix the two runs), and a run without
// VTU output removes them all with the earlier solution.pvd.

#include <filesystem>

#include "tests.h"

namespace
{
  /// The .pvtu and .vtu files in @p directory, and whether solution.pvd is
  /// there.
  std::pair<unsigned int, unsigned int>
  count_files(const std::string &directory, bool &pvd)
  {
    unsigned int pvtu = 0, vtu = 0;
    pvd = false;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      {
        const std::string name = entry.path().filename().string();
        if (name == "solution.pvd")
          pvd = true;
        else if (name.size() > 5 && name.substr(name.size() - 5) == ".pvtu")
          ++pvtu;
        else if (name.size() > 4 && name.substr(name.size() - 4) == ".vtu")
          ++vtu;
      }
    return {pvtu, vtu};
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  std::filesystem::remove_all("earlier");
  const auto prm = [](const double end_time, const bool vtu) {
    return bar_prm(2, "N-CS++", 20, 0.025, end_time) +
           "subsection Output\n  set Write vtu = " + (vtu ? "true" : "false") +
           "\n  set Output interval = 0.05\nend\n"
           "set Output directory = earlier\n";
  };
  bool pvd = false;
  run(prm(0.5, true));
  const auto first = count_files("earlier", pvd);
  log() << "a run to 0.5 s: " << first.first << " .pvtu, " << first.second
        << " .vtu, solution.pvd: "
        << check(first.first == 11 && first.second == 11 && pvd) << "\n";
  run(prm(0.2, true));
  const auto second = count_files("earlier", pvd);
  log() << "then a run to 0.2 s in the same directory: " << second.first
        << " .pvtu, " << second.second << " .vtu, solution.pvd: "
        << check(second.first == 5 && second.second == 5 && pvd) << "\n";
  run(prm(0.2, false));
  const auto third = count_files("earlier", pvd);
  log() << "then a run without VTU: " << third.first << " .pvtu, "
        << third.second << " .vtu, solution.pvd " << (pvd ? "" : "removed")
        << ": " << check(third.first == 0 && third.second == 0 && !pvd) << "\n";
}
