// The columns momentum_transfer and displacement_transfer: the largest
// change of a body's momentum and of its mean displacement in the mesh
// transfers since the last row. A bar vibrating in free flight (initial
// strain 0.3, nothing to hit before T = 3 s), N-CS++, the mesh adapted every
// 2 steps by Kelly's indicator of the velocity (half of the cells
// coarsened; the recovery indicator coarsened only where the velocity is
// uniform, which a transfer keeps exactly):
// without contact and loads a step keeps the momentum (Theorem 3.1) and
// moves the mean displacement by tau/2 (p^n + p^{n+1})/m, so that a row's
// change of the momentum column beyond that is the transfer's, and of the
// mean displacement beyond tau p/m too. Checked: both columns equal those
// changes (to 1e-10 of the momentum and of tau v0; the steps' CG at a
// tolerance of 1e-12, which the momentum's conservation is only as good
// as), some transfers change the momentum (by more than 1e-9 of it), the
// rows without a transfer (energy_transfer = 0) have zeros; a uniform mesh
// has no such columns. Also on two MPI ranks
// (transfer_motion.mpirun=2), with the same output.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const unsigned int cells = 16;
  const double       tau = 1. / cells / 2., v0 = 1., H = 0.1, m = 1. * H;
  const std::string  free_flight =
    scene_entries("Bar impact",
                  "    set Initial gap = 5\n    set Initial strain = 0.3\n");
  const Statistics s =
    run(bar_prm(2, "N-CS++", cells, tau, 3., free_flight) + tight_steps() +
        "subsection Mesh refinement\n  set Refinement interval = 2\n"
        "  set Maximum level = 2\n  set Criteria = kelly velocity\n"
        "  set Coarsen fraction = 0.5\n"
        "end\nset Output directory = output-adaptive\n");
  // (x and y: on two ranks the Kelly mesh is not symmetric, and a transfer
  // changes the momentum across the bar too)
  const auto px = s.column("momentum_x"), py = s.column("momentum_y"),
             dx            = s.column("mean_displacement_x"),
             dy            = s.column("mean_displacement_y"),
             p_transfer    = s.column("momentum_transfer"),
             d_transfer    = s.column("displacement_transfer"),
             energy        = s.column("energy_transfer");
  double momentum_mismatch = 0., displacement_mismatch = 0., largest = 0.,
         without         = 0.;
  unsigned int transfers = 0;
  for (unsigned int i = 1; i < px.size(); ++i)
    {
      const double dp = std::hypot(px[i] - px[i - 1], py[i] - py[i - 1]),
                   dd = std::hypot(dx[i] - dx[i - 1] - tau * px[i] / m,
                                   dy[i] - dy[i - 1] - tau * py[i] / m);
      momentum_mismatch =
        std::max(momentum_mismatch, std::abs(dp - p_transfer[i]));
      displacement_mismatch =
        std::max(displacement_mismatch, std::abs(dd - d_transfer[i]));
      largest = std::max(largest, p_transfer[i]);
      if (energy[i] != 0.)
        ++transfers;
      else
        without = std::max(without, p_transfer[i] + d_transfer[i]);
    }
  log() << "a vibrating bar in free flight, adapted every 2 steps: "
        << (transfers > 10 ? "more than 10" : "few") << " mesh changes\n";
  log() << "  momentum_transfer is the row's change of the momentum: "
        << check(momentum_mismatch <= 1e-10 * m * v0)
        << "\n  displacement_transfer the row's change of the mean "
           "displacement beyond tau p/m: "
        << check(displacement_mismatch <= 1e-10 * tau * v0)
        << "\n  some transfers change the momentum (by more than 1e-9 of "
           "it): "
        << check(largest > 1e-9 * m * v0)
        << "\n  rows whose mesh did not change have zeros: "
        << check(without == 0.) << "\n";

  const Statistics uniform =
    run(bar_prm(2, "N-CS++", cells, tau, 0.1, free_flight) +
        "set Output directory = output-uniform\n");
  log() << "a uniform mesh has no transfer columns: "
        << check(!uniform.has_column("momentum_transfer") &&
                 !uniform.has_column("displacement_transfer"))
        << "\n";
}
