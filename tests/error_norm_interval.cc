// 'Postprocess/Error norm interval = output times' integrates the
// energy-norm error only at the output times (every Output/Output interval),
// the first and the last step, and leaves nan in the other rows, whether or
// not VTU files are written ('Write vtu'). The 2D bar impact with an output
// every 4 steps: the norm must be there exactly at steps 0, 4, 8, ..., 40,
// with VTU files and without, and equal there to the norm of a run that
// integrates it every step. (With Write vtu = false, the next output time
// used to stay at the first one, and the norm ran every step from then on.)
// The timer section "sampled norms" of summary.txt must count the
// evaluations (it counted every step), and a static solve of a scene whose
// exact solution is the dynamics' has no error column (it compared the
// static state with the dynamics at End time).

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  // the calls of the timer section "sampled norms" in summary.txt
  const auto norm_calls = []() {
    return timer_calls("output-N-CS++-40/summary.txt", "sampled norms");
  };
  const double tau   = 0.0125;
  auto         solve = [&](const std::string &interval, const bool vtu) {
    return run(bar_prm(2,
                       "N-CS++",
                       40,
                       tau,
                       0.5,
                       std::string("subsection Output\n"
                                           "  set Output interval = 0.05\n"
                                           "  set Write vtu = ") +
                         (vtu ? "true" : "false") +
                         "\nend\n"
                                 "subsection Postprocess\n"
                                 "  subsection Error energy norm\n"
                                 "    set Interval = " +
                         interval + "\n  end\nend\n"));
  };
  const auto every = solve("every step", false).column("error_energy_norm");
  log() << "every step: " << every.size() << " rows, the norm in all: "
        << check(std::none_of(every.begin(),
                              every.end(),
                              [](const double e) { return std::isnan(e); }))
        << "; sampled norms: " << norm_calls() << " calls\n";
  for (const bool vtu : {false, true})
    {
      const auto sampled =
        solve("output times", vtu).column("error_energy_norm");
      const unsigned int calls       = norm_calls();
      bool               right_steps = sampled.size() == every.size();
      double             difference  = 0.;
      unsigned int       n_sampled   = 0;
      for (unsigned int i = 0; right_steps && i < sampled.size(); ++i)
        {
          const bool due = (i % 4 == 0);
          right_steps    = right_steps && (std::isnan(sampled[i]) != due);
          if (due && !std::isnan(sampled[i]))
            {
              ++n_sampled;
              difference =
                std::max(difference,
                         std::abs(sampled[i] - every[i]) / max_of(every));
            }
        }
      log() << "output times, Write vtu = " << (vtu ? "true" : "false")
            << ": the norm in " << n_sampled
            << " rows, exactly at steps 0, 4, ..., 40: " << check(right_steps)
            << "; equal to the every-step norm (1e-12): "
            << check(right_steps && difference <= 1e-12)
            << "; sampled norms: " << calls << " calls\n";
    }
  const Statistics statics = run(
    bar_prm(2,
            "static",
            40,
            tau,
            0.5,
            "subsection Postprocess\n"
            "  subsection Error energy norm\n"
            "    set Interval = every step\n  end\nend\n" +
              // held at its far end (a free bar is refused as singular)
              scene_entries("Bar impact", "    set Fixed far end = true\n")));
  log() << "static solve: no error_energy_norm column: "
        << check(std::find(statics.columns.begin(),
                           statics.columns.end(),
                           "error_energy_norm") == statics.columns.end())
        << "\n";
}
