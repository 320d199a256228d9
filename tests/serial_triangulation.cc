// Mesh/Triangulation = serial (deal.II's Triangulation on one rank instead
// of p4est's) against the distributed triangulation, on adaptive meshes:
// - the adaptive bar (H = 0.25, 32 cells along, levels 0 to 2, the recovery
//   indicator every 2 steps, p = 1, assembled S) to t = 0.6 s; two bars of
//   4 and 5 cells across adapted by the recovery indicator (two bodies,
//   contact rows on the adapted mesh) with p = 2 and the matrix-free S; a
//   3D bar (p = 1, the recovery indicator); the 2D bar with p = 2 and the
//   p-multigrid (its linear level on the same triangulation) refined at the
//   contact zone; all with hanging nodes: the same mesh after every
//   adaptation (cells and DoFs in every row: both mark the same cells with
//   the same thresholds and balance the same way), and the statistics
//   agree to 1e-7 apart from the iteration counts (the cells and DoFs are
//   numbered differently, so the sums differ in round-off, which CG's
//   tolerance of 1e-12 relative to the right-hand side lets grow to 4.5e-9
//   in the normal velocity of the active nodes);
// - a serial run of two bars adapted by the recovery indicator, stopped at
//   a checkpoint and resumed, agrees with the uninterrupted one to 1e-8 (the
//   checkpoint stores the refinement tree and the vectors cell by cell; the
//   resumed mesh numbers its cells otherwise, so round-off, not bit for bit);
// - a checkpoint of the serial triangulation is not resumed with the
//   distributed one (a parameter that must not change).
// On two ranks (serial_triangulation.mpirun=2) 'serial' is refused with a
// message naming the parameter and the number of ranks.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const auto triangulation = [](const std::string &kind) {
    return "subsection Mesh\n  set Triangulation = " + kind + "\nend\n";
  };
  if (testing::n_ranks() > 1)
    {
      std::string message;
      try
        {
          run(tight_steps() +
              bar_prm(2, "N-CS++", 10, 0.025, 0.1, triangulation("serial")));
        }
      catch (const std::exception &e)
        {
          message = e.what();
        }
      log() << "serial on 2 ranks refused, naming the parameter and the "
            << "ranks: "
            << check(message.find("Mesh/Triangulation = serial") !=
                       std::string::npos &&
                     message.find("this run has 2 ranks") != std::string::npos)
            << "\n";
      return 0;
    }

  struct Case
  {
    std::string name, prm;
  };
  const std::string bar =
    bar_prm(2,
            "N-CS++",
            32,
            1. / 256.,
            0.6,
            scene_entries("Bar impact", "    set Height = 0.25\n") +
              "subsection Mesh refinement\n"
              "  set Refinement interval = 2\n"
              "  set Maximum level = 2\n"
              "  set Initial contact refinements = 2\n"
              "  set Criteria = recovery velocity\n"
              "end\n");
  const std::string two_bars =
    bar_prm(2,
            "N-CS++",
            20,
            1. / 80.,
            1.,
            recovery_two_bars_prm() +
              "set Polynomial degree = 2\n"
              "subsection Contact solver\n  set Step matrix = matrix-free\n"
              "end\n");
  const std::string bar_3d = bar_prm(3,
                                     "N-CS++",
                                     8,
                                     1. / 32.,
                                     0.3,
                                     "subsection Mesh refinement\n"
                                     "  set Refinement interval = 2\n"
                                     "  set Maximum level = 1\n"
                                     "  set Initial contact refinements = 1\n"
                                     "  set Criteria = recovery velocity\n"
                                     "end\n");
  const std::string multigrid =
    bar_prm(2,
            "N-CS++",
            20,
            1. / 40.,
            0.4,
            q2_contact_zone_prm() +
              "subsection Contact solver\n  set Step matrix = matrix-free\n"
              "  set Preconditioner = multigrid\nend\n");
  for (const Case &c :
       {Case{"bar, p = 1", bar},
        Case{"two bars, p = 2, matrix-free S", two_bars},
        Case{"3D bar, p = 1", bar_3d},
        Case{"bar, p = 2, p-multigrid, contact zone", multigrid}})
    {
      const Statistics distributed = run(
        tight_steps() + c.prm + "set Output directory = results-distributed\n");
      const Statistics serial =
        run(tight_steps() + c.prm + triangulation("serial") +
            "set Output directory = results-serial\n");
      const bool same_meshes =
        distributed.column("cells") == serial.column("cells") &&
        distributed.column("dofs") == serial.column("dofs");
      const auto cells      = serial.column("cells");
      const auto comparison = compare_solvers(distributed, serial);
      std::cout << c.name << ": largest difference "
                << comparison.difference.first << " in "
                << comparison.difference.second << std::endl;
      log() << c.name << ": " << serial.rows.size() - 1 << " steps, "
            << max_of(cells) << " cells at most (" << cells[0]
            << " at first); the same mesh in every row: "
            << check(same_meshes && max_of(cells) > cells[0])
            << "; the statistics agree to 1e-7: "
            << check(comparison.difference.first <= 1e-7) << "\n";
    }

  // summary.txt says which triangulation held the mesh (the last case's)
  const auto summary_says = [](const std::string &directory,
                               const std::string &line) {
    std::ifstream     in(directory + "/summary.txt");
    std::stringstream text;
    text << in.rdbuf();
    return text.str().find("\n" + line + "\n") != std::string::npos;
  };
  log() << "summary.txt names the triangulation: "
        << check(
             summary_says("results-serial",
                          "parallel: 1 MPI rank(s), serial triangulation") &&
             summary_says("results-distributed",
                          "parallel: 1 MPI rank(s), distributed "
                          "triangulation (p4est)"))
        << "\n";

  // checkpoint and resume of the serial triangulation: the two bars of
  // tests/checkpoint_restart, stopped at t = 0.6375 s (step 102), where the
  // finer side of the interface is no longer the slave side chosen at t = 0
  const auto checkpointed = [&](const std::string &run,
                                const double       end,
                                const bool         resume) {
    return bar_prm(2, "N-CS++", 40, 1. / 160., end, recovery_two_bars_prm()) +
           triangulation("serial") + "set Output directory = results-" + run +
           "\n" + "subsection Checkpointing\n  set Interval in steps = 102\n" +
           "  set Resume = " + (resume ? "true" : "false") + "\nend\n";
  };
  const Statistics full = run(tight_steps() + checkpointed("full", 1., false));
  run(tight_steps() + checkpointed("split", 0.6375, false));
  const Statistics resumed =
    run(tight_steps() + checkpointed("split", 1., true));
  const auto comparison = compare_solvers(full, resumed);
  std::cout << "resumed: largest difference " << comparison.difference.first
            << " in " << comparison.difference.second << std::endl;
  log() << "serial, stopped at step 102 and resumed: the same meshes: "
        << check(full.column("dofs") == resumed.column("dofs"))
        << "; the statistics agree to 1e-8: "
        << check(comparison.difference.first <= 1e-8) << "\n";

  std::string message;
  try
    {
      run(tight_steps() +
          bar_prm(2, "N-CS++", 40, 1. / 160., 1., recovery_two_bars_prm()) +
          "set Output directory = results-split\n" +
          "subsection Checkpointing\n  set Resume = true\nend\n");
    }
  catch (const std::exception &e)
    {
      message = e.what();
    }
  log() << "its checkpoint is refused by the distributed triangulation, "
        << "naming the parameter: "
        << check(message.find("Mesh/Triangulation") != std::string::npos)
        << "\n";
}
