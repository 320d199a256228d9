// 'Time step control = adaptive' on the bar impact with an impact time off
// the time grid (g0 = 0.1037 m, v = 1 m/s: contact at t = 0.1037 s; tau =
// h/2c = 0.0125 s). For N-CI, N-CS and N-CS++:
// - event location: the first step with active rows starts within tau/100
//   of the exact contact time (fixed tau: the nearest grid time, 0.0037 s
//   = 0.3 tau away, fails this);
// - the energy statement (Theorem 3.2): energy_balance grows in no step by
//   more than 1e-9 of the initial energy, as with fixed tau;
// - N-CS++: persistency (eq. 19), udot.nu = 0 at active nodes;
// - bookkeeping: the times are the sums of the recorded time steps, the
//   last step ends at End time, every level is Time step * 2^k within
//   [Minimum, Maximum], and tau grows above Time step in the free flight
//   before the impact;
// - the step matrices S are cached per level: the summary's count of S
//   built lies between the number of distinct tau of the accepted steps
//   and that plus the repeated steps, and is below 1 + the number of
//   changes of tau (which a rebuild at every change would need).
// - N-CS++: the running sum of meas Gamma* (eq. 40) is the sum of the
//   steps' measures.
// On prm/hertz_drop.prm (to 0.6 s, adaptive from tau = 0.01 s), where the
// contact zone grows node by node: 'Event location = onset and separation'
// shortens at most two steps (the onset, which N-CS++'s look-ahead takes in
// two), 'every row' one per node that comes into contact (more than 5),
// and both keep the energy statement.
// Two bars (phi_h, non-matching meshes), adaptive: the number of steps,
// of shortened steps and the contact start are printed; the 2-rank variant
// (adaptive_time_step.mpirun=2) must print the same (event location once
// depended on round-off that differs between 1 and 2 ranks).
// And a checkpointed adaptive run resumed from half time, or from the step
// before the located release, gives the same statistics as the
// uninterrupted one (tau levels, the estimator's history and the rows'
// forces and states are in the checkpoint).

#include <fstream>
#include <iterator>
#include <set>
#include <tuple>

#include "tests.h"


namespace
{
  /// The number before @p what in the summary's "time steps:" line of
  /// @p directory (-1 if none).
  int
  summary_count(const std::string &directory, const std::string &what)
  {
    std::ifstream file(directory + "/summary.txt");
    std::string   line, text;
    while (std::getline(file, line))
      if (line.rfind("time steps:", 0) == 0)
        text = line;
    const auto end = text.find(what);
    if (end == std::string::npos)
      return -1;
    const auto begin = text.rfind(' ', end - 1);
    return std::stoi(text.substr(begin + 1, end - begin - 1));
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const double      tau = 0.0125, contact_time = 0.1037;
  const std::string adaptive =
    scene_entries("Bar impact", "    set Initial gap = 0.1037\n") +
    "subsection Time integration\n"
    "  set Time step control = adaptive\n"
    "  set Minimum time step = 0.0015625\n"
    "  set Maximum time step = 0.05\n"
    "  set Time step tolerance = 0.003\n"
    "end\n";
  const std::string off_grid =
    scene_entries("Bar impact", "    set Initial gap = 0.1037\n");

  // the start of the first step with active rows
  auto contact_start = [](const Statistics &s) {
    const auto t = s.column("time"), a = s.column("active_nodes");
    for (unsigned int i = 1; i < t.size(); ++i)
      if (a[i] > 0)
        return t[i - 1];
    return -1.;
  };
  auto largest_balance_increase = [](const Statistics &s) {
    const auto b        = s.column("energy_balance");
    double     increase = -1e300;
    for (unsigned int i = 1; i < b.size(); ++i)
      increase = std::max(increase, b[i] - b[i - 1]);
    return increase;
  };

  for (const std::string scheme : {"N-CI", "N-CS", "N-CS++"})
    {
      const Statistics fixed =
        run(tight_steps() + bar_prm(2, scheme, 40, tau, 2.5, off_grid));
      const Statistics s =
        run(tight_steps() + bar_prm(2, scheme, 40, tau, 2.5, adaptive));
      const auto t = s.column("time"), dt = s.column("time_step");

      const double fixed_miss = std::abs(contact_start(fixed) - contact_time);
      const double miss       = std::abs(contact_start(s) - contact_time);
      log() << scheme << ": contact starts " << fmt(fixed_miss / tau, 2)
            << " tau from the exact time with fixed tau; adaptive within "
            << "tau/100: " << check(miss <= 0.01 * tau) << "\n";
      std::cout << scheme << ": " << t.size() - 1 << " steps, contact start "
                << contact_start(s) << ", final error "
                << s.column("error_energy_norm").back() << " (fixed "
                << fixed.column("error_energy_norm").back() << ")" << std::endl;

      const double energy0 = s.column("energy_total")[0];
      log() << "  energy_balance grows by at most 1e-9 E0 per step: "
            << check(largest_balance_increase(s) <= 1e-9 * energy0) << "\n";
      if (scheme == "N-CS++")
        {
          const auto measure = s.column("critical_measure"),
                     sum     = s.column("critical_measure_sum");
          double running = 0., deviation = 0.;
          for (unsigned int i = 0; i < measure.size(); ++i)
            {
              running += measure[i];
              deviation = std::max(deviation, std::abs(running - sum[i]));
            }
          log() << "  sum of meas Gamma* over the steps as recorded: "
                << check(deviation < 1e-12 && running > 0.) << "\n";
          double normal_velocity = 0.;
          for (const double v : s.column("max_active_normal_velocity"))
            normal_velocity = std::max(normal_velocity, v);
          log() << "  persistency at active nodes (< 1e-10 m/s): "
                << check(normal_velocity < 1e-10) << "\n";
        }

      bool sums = true, levels_ok = true;
      bool grew = false;
      for (unsigned int i = 1; i < t.size(); ++i)
        {
          grew           = grew || (t[i] < contact_time && dt[i] > 1.5 * tau);
          sums           = sums && std::abs(t[i] - t[i - 1] - dt[i]) <= 1e-12;
          const double k = std::log2(dt[i] / tau);
          if (std::abs(k - std::round(k)) < 1e-12)
            levels_ok = levels_ok && dt[i] >= 0.0015625 * (1 - 1e-12) &&
                        dt[i] <= 0.05 * (1 + 1e-12);
        }
      log() << "  t_n+1 - t_n = recorded tau, last step ends at End time, "
            << "levels Time step * 2^k in [min, max]: "
            << check(sums && std::abs(t.back() - 2.5) < 1e-12 && levels_ok)
            << "\n";
      log() << "  tau grows in the free flight before the impact: "
            << check(grew) << "\n";

      // the summary's counts
      const std::string dir      = "output-" + scheme + "-40";
      const int         built    = summary_count(dir, " step matrices S built");
      const int         repeated = summary_count(dir, " steps repeated");
      // each located event and each passed output time may leave the S
      // of a trial that was not accepted
      const int located = summary_count(dir, " steps shortened");
      const int passed =
        std::max(0, summary_count(dir, " output times passed"));
      std::set<double> distinct(dt.begin() + 1, dt.end());
      unsigned int     changes = 0;
      for (unsigned int i = 2; i < dt.size(); ++i)
        changes += (dt[i] != dt[i - 1]);
      std::cout << "  S built " << built << ", distinct tau " << distinct.size()
                << ", repeated " << repeated << ", changes of tau " << changes
                << std::endl;
      log() << "  S built once per tau (cache): "
            << check(built >= int(distinct.size()) &&
                     built <=
                       int(distinct.size()) + repeated + located + passed &&
                     built <= int(changes))
            << "\n";
    }

  // a contact zone that grows node by node: which events are located
  {
    std::ifstream     file(std::string(DYNCONTACT_PRM_DIR) + "/hertz_drop.prm");
    const std::string base((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    for (const std::string location : {"onset and separation", "every row"})
      {
        const std::string dir = "output-hertz-" + location.substr(0, 5);
        const Statistics  s =
          run(tight_steps() + base + "set Output directory = " + dir +
              "\nsubsection Output\n  set Write vtu = false\nend\n"
              "subsection Time integration\n  set End time = 0.6\n"
              "  set Time step control = adaptive\n"
              "  set Minimum time step = 0.00125\n"
              "  set Maximum time step = 0.08\n"
              "  set Time step tolerance = 0.003\n"
              "  set Event location = " +
              location + "\nend\n");
        const int located =
          summary_count(dir, " steps shortened to a contact event");
        std::cout << "Hertz drop, " << location << ": " << located
                  << " events located, " << s.rows.size() - 1 << " steps"
                  << std::endl;
        log() << "Hertz drop, Event location = " << location << ": "
              << (location == "every row" ? "more than 5 steps shortened: " :
                                            "at most 2 steps shortened: ")
              << check(location == "every row" ? located > 5 :
                                                 located >= 1 && located <= 2)
              << "; energy_balance grows by at most 1e-9 of its scale: "
              << check(largest_balance_increase(s) <=
                       1e-9 * s.column("energy_total")[0])
              << "\n";
      }
  }

  // two bodies: the same steps on any number of ranks
  {
    const Statistics s =
      run(tight_steps() +
          bar_prm(2,
                  "N-CS++",
                  40,
                  tau,
                  2.5,
                  scene_prm("two bars",
                            "    set Cells across = 2\n"
                            "    set Cells across body 2 = 3\n"
                            "    set Initial gap = 0.1037\n") +
                    adaptive) +
          "set Output directory = output-two-bars\n");
    log() << "two bars, adaptive: " << s.rows.size() - 1 << " steps, "
          << summary_count("output-two-bars",
                           " steps shortened to a contact event")
          << " shortened to a contact event; contact starts within tau/100 "
          << "of the exact time: "
          << check(std::abs(contact_start(s) - contact_time) <= 0.01 * tau)
          << "\n";
  }

  // resumed from a checkpoint at half time, and from the step before the
  // located release (the rows' forces of that step are in the checkpoint;
  // without them the first step after the resume located no release): the
  // same statistics
  auto prm = [&](const std::string &run,
                 const double       end,
                 const bool         resume,
                 const unsigned int interval) {
    return bar_prm(2, "N-CS++", 40, tau, end, adaptive) +
           "set Output directory = results-adaptive-" + run + "\n" +
           "subsection Checkpointing\n  set Interval in steps = " +
           std::to_string(interval) +
           "\n  set Resume = " + (resume ? "true" : "false") + "\nend\n";
  };
  const Statistics full = run(tight_steps() + prm("full", 2.5, false, 60));
  // the release: the first step without contact force after one with it
  const auto   force   = full.column("contact_force");
  const auto   times   = full.column("time");
  unsigned int release = 0;
  for (unsigned int i = 1; i < force.size() && release == 0; ++i)
    if (force[i] == 0. && force[i - 1] > 0.)
      release = i;
  log() << "the release is located (a shortened step): "
        << check(release > 1 && full.column("time_step")[release] < 0.99 * tau)
        << "\n";
  for (const auto &[what, end, interval] :
       {std::make_tuple(std::string("at half time"), 1.25, 60u),
        std::make_tuple(std::string("from the step before the release"),
                        times[release - 1],
                        release - 1)})
    {
      run(tight_steps() +
          prm("split-" + std::to_string(interval), end, false, interval));
      const Statistics resumed =
        run(tight_steps() +
            prm("split-" + std::to_string(interval), 2.5, true, interval));
      double difference = 0.;
      bool   same_shape = full.rows.size() == resumed.rows.size() &&
                        full.columns == resumed.columns;
      for (unsigned int c = 0; same_shape && c < full.columns.size(); ++c)
        if (full.columns[c] != "step_wall_time")
          for (unsigned int i = 0; i < full.rows.size(); ++i)
            difference =
              std::max(difference,
                       std::abs(full.rows[i][c] - resumed.rows[i][c]));
      std::cout << "resumed " << what << ": " << resumed.rows.size()
                << " rows, full " << full.rows.size() << ", largest difference "
                << difference << std::endl;
      log() << "adaptive run resumed " << what << ": same statistics (1e-12): "
            << check(same_shape && difference <= 1e-12) << "\n";
    }
}
