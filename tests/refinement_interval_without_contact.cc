// Mesh refinement/Refinement interval without contact: while no contact is
// near, the mesh adapts only after every 16th step instead of every 2nd. The
// bar against the wall (H = 0.25 m, 0.5 m long, 16 cells along, 0.1 m from
// the wall at 1 m/s), levels 0 to 2 by the velocity jump and the contact
// zone, Keep body motion, tau = h_min / 2c, N-CS++, run to 0.5 s after the
// release at 1.1 s. Against the same run adapted every 2 steps throughout:
// - in the flight after the release (from 0.05 s after it on) the mesh
//   changes only after multiples of 16 steps, where the other run changes it
//   after other steps too;
// - so it does in the 0.05 s after the release (from 2 steps after it on),
//   while the bar's end recedes through the contact zone (two cell sizes
//   from the wall): a node whose gap does not close is not near
//   (when it counted, the mesh changed there twice, measured on
//   2026-12-01);
// - during the contact it adapts every 2 steps (mesh changes after steps
//   that are not multiples of 16);
// - the approach counts as near (the gap, less the distance the bar closes
//   in 2 steps, is below two cell sizes at the node): the mesh
//   changes after steps that are not multiples of 16 before the impact, and
//   the contact's start and end, the peak force and the momentum after the
//   release are the other run's (measured on 2026-11-30: the same steps
//   and peak force, the momentum 4e-9 of it apart);
// - its mesh changes 92 times against 135;
// - resumed from a checkpoint at a step in the flight that the option
//   skips, the run goes on as the uninterrupted one.
// With the active sets alone as the test of a near contact (tried), the
// approach adapted only at step 16, the contact zone was not refined ahead
// of the impact, and the contact's start, the peak force and the momentum
// differed.
// A rigid plane that moves onto a block at rest (the block of
// prm/meshes/two_blocks.msh, levels 0 to 3 by Kelly's indicator and the
// contact zone every 2 steps, contact from step 96): the obstacle's own
// motion closes the gap, so the approach counts as near with m = 16 too;
// the mesh changes after step 86 as with m = 0, and the first contact step
// has the other run's active nodes and force. (Counting the nodes'
// velocities alone, the contact began on the coarse mesh: 161 active nodes
// against 321, 14 % less force; measured on 2026-12-01.) On 1 and 2
// ranks.

#include "tests.h"

namespace
{
  using namespace testing;

  struct Run
  {
    std::pair<double, double> contact;
    double                    peak_force = 0.;
    double                    momentum   = 0.; // after the release
    // mesh changes after steps that are not multiples of 16
    unsigned int approach_changes = 0, contact_changes = 0, flight_changes = 0,
                 release_changes = 0;
    unsigned int        changes  = 0; // in all
    std::vector<double> dofs;
  };

  const double tau = 1. / 256.;

  /// The block at rest and the rigid plane that moves onto it, adapted
  /// every 2 steps and, without contact, every @p without_contact.
  std::string
  obstacle_prm(const unsigned int without_contact)
  {
    return "set Dimension = 2\nset Output directory = obstacle-" +
           std::to_string(without_contact) + "\n" +
           scene_prm("gmsh",
                     "    set Mesh file = " + std::string(DYNCONTACT_PRM_DIR) +
                       "/meshes/two_blocks.msh\n"
                       "    set Bodies = 1; 2\n"
                       "    set Contact tags = 10;\n"
                       "    set Dirichlet tags = 11, 13\n"
                       "    set Contact pairs = 1 : obstacle 1\n"
                       "    set Obstacles = plane 0, -0.7375 normal 0, 1 "
                       "moving 0, 1.0*t\n") +
           "subsection Material\n  set Young's modulus = 100\n"
           "  set Poisson's ratio = 0.3\n  set Density = 1\n"
           "  set Viscous shear modulus = 0.1\nend\n"
           "subsection Mesh refinement\n  set Refinement interval = 2\n"
           "  set Refinement interval without contact = " +
           std::to_string(without_contact) +
           "\n  set Maximum level = 3\n  set Refine fraction = 0.05\n"
           "  set Coarsen fraction = 0.5\n"
           "  set Criteria = kelly velocity, contact zone\nend\n"
           "subsection Time integration\n  set Time step = 0.0025\n"
           "  set End time = 0.25\nend\n"
           "subsection Output\n  set Write vtu = false\nend\n";
  }

  std::string
  entries(const unsigned int without_contact)
  {
    return scene_entries("Bar impact",
                         "    set Height = 0.25\n"
                         "    set Length = 0.5\n"
                         "    set Cells along length = 16\n") +
           "subsection Mesh refinement\n"
           "  set Refinement interval = 2\n"
           "  set Refinement interval without contact = " +
           std::to_string(without_contact) +
           "\n"
           "  set Maximum level = 2\n"
           "  set Criteria = velocity jump, contact zone\n"
           "  set Keep body motion = true\n"
           "end\n";
  }

  Run
  simulate(const unsigned int without_contact)
  {
    const Statistics s =
      run(bar_prm(2, "N-CS++", 32, tau, 1.6, entries(without_contact)));
    const auto t     = s.column("time");
    const auto step  = s.column("step");
    const auto cells = s.column("cells");
    const auto force = s.column("contact_force");
    const auto p     = s.column("momentum_x");
    Run        r;
    r.contact    = contact_interval(s);
    r.peak_force = max_of(force);
    r.momentum   = p.back();
    r.dofs       = s.column("dofs");
    for (unsigned int i = 1; i < t.size(); ++i)
      if (cells[i] != cells[i - 1])
        {
          ++r.changes;
          // (the change is made after the row's step, seen in the next row)
          if (static_cast<unsigned int>(step[i - 1]) % 16 == 0)
            continue;
          if (t[i] < r.contact.first)
            ++r.approach_changes;
          else if (t[i] <= r.contact.second)
            ++r.contact_changes;
          else if (t[i] > r.contact.second + 0.05)
            ++r.flight_changes;
          else if (t[i] > r.contact.second + 2. * tau)
            ++r.release_changes;
        }
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const Run every = simulate(0), sparse = simulate(16);
  log() << "every 2 steps: the mesh changes after other steps than "
        << "multiples of 16 in the flight (more than 5 times): "
        << check(every.flight_changes > 5) << "\n";
  log() << "without contact every 16: never in the flight: "
        << check(sparse.flight_changes == 0) << "\n";
  log() << "  in the 0.05 s after the release, as the bar recedes through "
        << "the contact zone: never: " << check(sparse.release_changes == 0)
        << "\n";
  log() << "  in the contact more than 10 times: "
        << check(sparse.contact_changes > 10) << "\n";
  log() << "  in the approach (the contact zone ahead of the impact): "
        << check(sparse.approach_changes >= 1) << "\n";
  log() << "  contact start and end at the same steps: "
        << check(
             std::abs(sparse.contact.first - every.contact.first) < 0.5 * tau &&
             std::abs(sparse.contact.second - every.contact.second) < 0.5 * tau)
        << "\n";
  log() << "  peak force and momentum after the release within 1e-6 of the "
        << "other run's: "
        << check(std::abs(sparse.peak_force - every.peak_force) <
                   1e-6 * every.peak_force &&
                 std::abs(sparse.momentum - every.momentum) <
                   1e-6 * std::abs(every.momentum))
        << "\n";
  log() << "  fewer mesh changes in all: "
        << check(sparse.changes < every.changes) << "\n";
  // the plane moving onto the block at rest
  {
    const Statistics every_o  = run(obstacle_prm(0)),
                     sparse_o = run(obstacle_prm(16));
    const auto step = sparse_o.column("step"), cells = sparse_o.column("cells");
    const auto force        = sparse_o.column("contact_force"),
               force_every  = every_o.column("contact_force");
    const auto active       = sparse_o.column("active_nodes"),
               active_every = every_o.column("active_nodes");
    unsigned int first      = 0; // the first contact step's row
    while (first < force.size() && force[first] == 0.)
      ++first;
    bool approach = false; // a change after a step not a multiple of 16
    for (unsigned int i = 1; i < first && i < cells.size(); ++i)
      approach = approach || (cells[i] != cells[i - 1] &&
                              static_cast<unsigned int>(step[i - 1]) % 16 != 0);
    log() << "a plane moving onto a block at rest, without contact every 16: "
          << "the mesh changes in the approach: " << check(approach)
          << "; the first contact step, its active nodes and force are "
          << "those of the run adapted every 2 steps: "
          << check(first < force.size() && first < force_every.size() &&
                   force_every[first] > 0. &&
                   (first == 0 || force_every[first - 1] == 0.) &&
                   active[first] == active_every[first] &&
                   std::abs(force[first] - force_every[first]) <=
                     1e-9 * force_every[first])
          << "\n";
  }
  // a run that ends at step 330 (t = 1.289 s, in the flight), due to adapt
  // by Refinement interval but not by 16, resumed from its checkpoint
  // there: the resume skips the adaptation, as the uninterrupted run did
  const auto prm = [&](const double end, const bool resume) {
    return bar_prm(2, "N-CS++", 32, tau, end, entries(16)) +
           "set Output directory = resumed\n" + checkpointing(110, resume);
  };
  run(prm(330. * tau, false));
  const Statistics resumed = run(prm(1.6, true));
  const auto       p       = resumed.column("momentum_x");
  log() << "resumed at step 330: the DoFs and the momentum of the "
        << "uninterrupted run: "
        << check(resumed.column("dofs") == sparse.dofs &&
                 std::abs(p.back() - sparse.momentum) <=
                   1e-8 * std::abs(sparse.momentum))
        << "\n";
}
