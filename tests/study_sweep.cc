// The study driver (benchmarks/study.py) on a short sweep: bar impact (gap
// 0.1037 m, so that contact does not begin exactly at a time step), N-CI and
// N-CS++, two joint refinements of h and tau. Checks of its CSV: the error
// in the energy norm falls at the known rate under the joint refinement;
// N-CS++'s pressure overshoot stays below N-CI's; sum meas Gamma* of N-CS++
// is the measure of the contact boundary (0.1 m) once per impact, whatever
// tau. Then the plot
// script (benchmarks/plot_study.py) makes its three PNGs from a small CSV
// fixture (tests/study_fixture.csv).

#include <filesystem>
#include <map>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const std::string source = DYNCONTACT_SOURCE_DIR;
  const std::string python = DYNCONTACT_PYTHON;
  const std::string sweep  = run_clean(
    python + " " + source + "/benchmarks/study.py --prm " + source +
    "/prm/bar_impact.prm --out study.csv --work results-study --executable " +
    DYNCONTACT_EXECUTABLE +
    " --schemes N-CI,N-CS++ --tau0 0.025 --tau-levels 0,1 --mesh-levels 0,1"
     " --joint --reference-pressure 1"
     " --set 'Scene/Bar impact/Initial gap=0.1037'"
     " --set 'Scene/Bar impact/Cells along length=20'");
  log() << "sweep ran: "
        << check(sweep.find("command failed") == std::string::npos) << "\n";

  const auto rows = read_csv("study.csv");
  log() << "CSV rows: " << rows.size() << "\n";
  std::map<std::string, std::vector<std::map<std::string, std::string>>> by;
  for (const auto &r : rows)
    by[r.at("scheme")].push_back(r);
  for (const std::string scheme : {"N-CI", "N-CS++"})
    {
      // (the energy-norm error of the bar falls like h^0.3 behind the
      // fronts: tests/bar_impact_convergence, doc/results.md)
      const auto  &r    = by[scheme];
      const double rate = r.size() == 2 ?
                            std::log2(std::stod(r[0].at("error_max")) /
                                      std::stod(r[1].at("error_max"))) :
                            0.;
      log() << scheme << ": the error's rate under joint refinement of h and "
            << "tau " << fmt(rate, 2) << " (h^0.3 known; in [0.2, 0.45]): "
            << check(rate >= 0.2 && rate <= 0.45) << "\n";
    }
  bool overshoot = by["N-CI"].size() == 2 && by["N-CS++"].size() == 2;
  for (unsigned int i = 0; overshoot && i < 2; ++i)
    overshoot = std::stod(by["N-CS++"][i].at("pressure_overshoot")) <
                std::stod(by["N-CI"][i].at("pressure_overshoot"));
  log() << "N-CS++'s pressure overshoot below N-CI's: " << check(overshoot)
        << "\n";
  bool critical = by["N-CS++"].size() == 2;
  for (const auto &r : by["N-CS++"])
    critical = critical &&
               std::abs(std::stod(r.at("critical_measure_sum")) - 0.1) < 1e-9;
  log() << "N-CS++: sum meas Gamma* = 0.1 (one impact) at both tau: "
        << check(critical) << "\n";

  // the plots from the fixture
  const std::string plots =
    run_clean(python + " " + source + "/benchmarks/plot_study.py " +
              SOURCE_DIR + "/study_fixture.csv fixture bar");
  for (const std::string name : {"fixture_work_precision.png",
                                 "fixture_tau.png",
                                 "fixture_critical.png"})
    {
      std::ifstream in(name, std::ios::binary);
      char          magic[4] = {0, 0, 0, 0};
      in.read(magic, 4);
      log() << name << " is a PNG of more than 10 kB: "
            << check(magic[1] == 'P' && magic[2] == 'N' && magic[3] == 'G' &&
                     std::filesystem::exists(name) &&
                     std::filesystem::file_size(name) > 10000)
            << "\n";
    }
}
