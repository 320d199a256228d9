// Checkpoint/restart: a run stopped at half time (with a checkpoint there)
// and resumed with 'Resume = true' gives the same statistics (every column
// but the wall times, to 1e-10 relative) and the same final state as the
// uninterrupted run: for the bar impact (N-CS++) and for an adaptive
// two-bars run (the refined mesh is saved and loaded with p4est). So does a
// run stopped at a step after which the mesh adapts (the stopped run does
// not adapt after its last step; the resumed one adapts first), and one
// stopped between output times (its last step is an output, but the next
// output time stays where it was), and two bars adapted by the recovery
// indicator, stopped at t = 0.6375 s, where the finer side of the interface
// is no longer the slave side chosen at t = 0, on 1 and on 2 ranks (the
// checkpoint keeps that side), and a chain of four bars adapted by the
// recovery indicator, stopped at a step after which the adaptation leaves
// the mesh as it was (the resumed run makes its integrator all the same).
// A resumed input whose critical parameters differ (the time step) is
// refused with a message naming the parameter. Also on two MPI ranks
// (checkpoint_restart.mpirun=2) with the same output.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const std::string adaptive = adaptive_two_bars_prm();
  // a resume at half time; one at a step after which the mesh adapts (the
  // last step of the first run, where it does not); one at a step that is
  // no output time, where the error norm is sampled at output times
  struct Case
  {
    std::string  name, dir, extra;
    double       split;
    unsigned int split_step;
    unsigned int cells = 10;
    double       tau   = 0.025;
    // (the recovery indicator's meshes differ between 1 and 2 ranks)
    bool   print_final_state = true;
    double end               = 2.5;
  };
  // four bodies, adapted every 4 steps by the recovery indicator; at step
  // 200 the adaptation leaves the mesh as it is
  const std::string chain =
    scene_prm("bar chain",
              "    set Length = 1\n    set Height = 0.1\n"
              "    set Impact velocity = 1\n    set Initial gap = 0.1\n"
              "    set Cells along length = 10\n    set Cells across = 1\n") +
    "subsection Mesh refinement\n  set Refinement interval = 4\n"
    "  set Maximum level = 2\n  set Criteria = recovery velocity\n"
    "  set Refine fraction = 0.2\n  set Coarsen fraction = 0.3\nend\n";
  const std::string sampled = "subsection Output\n  set Output interval = 0.1\n"
                              "end\nsubsection Postprocess\n"
                              "  subsection Error energy norm\n"
                              "    set Interval = output times\n  end\nend\n";
  for (const Case &c :
       {Case{"bar impact", "bar", "", 1.25, 50},
        Case{"adaptive two bars", "two-bars", adaptive, 1.25, 50},
        Case{"adaptive two bars", "two-bars-refine", adaptive, 1.2, 48},
        Case{"bar impact", "bar-sampled", sampled, 1.225, 49},
        Case{"two bars, recovery indicator",
             "two-bars-sides",
             recovery_two_bars_prm(),
             0.6375,
             102,
             40,
             1. / 160.,
             false,
             1.25},
        Case{"adaptive bar chain, no change at the split",
             "chain",
             chain,
             2.5,
             200,
             10,
             0.0125,
             false,
             3.}})
    {
      auto prm =
        [&](const std::string &run, const double end, const bool resume) {
          return bar_prm(2, "N-CS++", c.cells, c.tau, end, c.extra) +
                 "set Output directory = results-" + c.dir + "-" + run + "\n" +
                 "subsection Checkpointing\n  set Interval in steps = " +
                 std::to_string(c.split_step) + "\n" +
                 "  set Resume = " + (resume ? "true" : "false") + "\nend\n";
        };
      const Statistics full = run(tight_steps() + prm("full", c.end, false));
      run(tight_steps() + prm("split", c.split, false));
      const Statistics resumed = run(tight_steps() + prm("split", c.end, true));

      // a sampled column is sampled in the same rows, but for the first
      // run's last step, which samples it
      const auto [difference, worst] =
        statistics_difference(full, resumed, c.split_step);
      std::cout << c.dir << ": largest difference " << difference << " in "
                << worst << std::endl;
      log() << c.name << ": " << full.rows.size() - 1 << " steps; resumed at "
            << "step " << c.split_step
            << ", the statistics agree to 1e-10: " << check(difference <= 1e-10)
            << "\n";
      if (c.print_final_state)
        {
          // in units of their size at t = 0 (the energy, the sum of the
          // bodies' momenta), so that numdiff's absolute tolerance (1e-6)
          // is a relative one
          const double p  = resumed.column("momentum_x")[0];
          const double p2 = resumed.has_column("momentum_x_body2") ?
                              resumed.column("momentum_x_body2")[0] :
                              0.;
          log() << "  final energy / E(0) "
                << fmt(resumed.column("energy_total").back() /
                         resumed.column("energy_total")[0],
                       6)
                << ", momentum / sum of the bodies' |momentum(0)| "
                << fmt(resumed.column("momentum_x").back() /
                         (std::abs(p - p2) + std::abs(p2)),
                       6)
                << "\n";
        }
    }

  // a changed time step is refused
  std::string message;
  try
    {
      run(tight_steps() + bar_prm(2, "N-CS++", 10, 0.0125, 2.5) +
          "set Output directory = results-bar-split\n"
          "subsection Checkpointing\n  set Resume = true\nend\n");
    }
  catch (const std::exception &e)
    {
      message = e.what();
    }
  log() << "a different time step is refused, naming it: "
        << check(message.find("Time integration/Time step") !=
                 std::string::npos)
        << "\n";
}
