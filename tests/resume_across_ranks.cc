// A checkpoint resumes on another number of ranks (p4est saves the mesh and
// the vectors in parallel): the two bars on an adaptive mesh with adaptive
// tau (phi_h, Kelly and contact-zone refinement every 4 steps, event
// location), stopped at half time on one rank and resumed on two, and
// stopped on two and resumed on one. Each resumed run reaches End time and
// agrees with the uninterrupted run on the ranks of its first half in the
// number of steps and in every column (but the wall times) to 1e-6 of the
// column's scale (the ranks' sums round differently; a wrong state read
// back differs by far more). Before, the uninterrupted run on two ranks
// stopped with Trilinos error -3 after an adaptation that repartitioned
// the mesh without changing the number of DoFs. Only as
// tests/resume_across_ranks.mpirun=2.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  const unsigned int rank = testing::this_rank();

  // rank 0 alone
  MPI_Comm one_rank;
  MPI_Comm_split(MPI_COMM_WORLD, rank == 0 ? 0 : MPI_UNDEFINED, 0, &one_rank);

  const std::string extra = adaptive_two_bars_prm() +
                            "subsection Time integration\n"
                            "  set Time step control = adaptive\n"
                            "end\n";
  auto prm = [&](const std::string &dir, const double end, const bool resume) {
    return bar_prm(2, "N-CS++", 10, 0.025, end, extra) +
           "set Output directory = results-" + dir + "\n" +
           "subsection Checkpointing\n  set Interval in steps = 20\n" +
           "  set Resume = " + (resume ? "true" : "false") + "\nend\n";
  };

  // the uninterrupted runs on one rank and on two (on an adaptive mesh
  // they differ: Kelly's indicators round differently, and cells near the
  // refinement threshold are marked differently)
  Statistics full_on_one;
  if (one_rank != MPI_COMM_NULL)
    full_on_one = dyncontact::run_simulation(prm("full-1", 2., false),
                                             one_rank,
                                             "test input");
  MPI_Barrier(MPI_COMM_WORLD);
  const Statistics full_on_two = run(prm("full-2", 2., false));
  log() << "uninterrupted: " << full_on_one.rows.size() - 1
        << " steps on 1 rank, " << full_on_two.rows.size() - 1
        << " on 2 ranks\n";

  for (const bool first_on_one : {true, false})
    {
      const std::string dir = first_on_one ? "one-two" : "two-one";
      // the first half, on one rank or on both
      if (!first_on_one)
        run(prm(dir, 1., false));
      else if (one_rank != MPI_COMM_NULL)
        dyncontact::run_simulation(prm(dir, 1., false), one_rank, "test input");
      MPI_Barrier(MPI_COMM_WORLD);
      // the second half, on the other
      Statistics resumed;
      if (first_on_one)
        resumed = run(prm(dir, 2., true));
      else if (one_rank != MPI_COMM_NULL)
        resumed = dyncontact::run_simulation(prm(dir, 2., true),
                                             one_rank,
                                             "test input");
      MPI_Barrier(MPI_COMM_WORLD);
      // against the uninterrupted run on the ranks of the first half
      const double d =
        rank == 0 ?
          statistics_difference(first_on_one ? full_on_one : full_on_two,
                                resumed)
            .first :
          0.;
      std::cout << dir << ": largest difference " << d << std::endl;
      log() << (first_on_one ? "1 rank, resumed on 2" : "2 ranks, resumed on 1")
            << ": reaches End time with the statistics of the uninterrupted "
               "run on "
            << (first_on_one ? 1 : 2)
            << " rank(s) to 1e-6: " << check(d <= 1e-6) << "\n";
    }
  if (one_rank != MPI_COMM_NULL)
    MPI_Comm_free(&one_rank);
}
