// Mesh refinement/Contact zone/Distance equal to the gap at t = 0: the
// contact zone holds the slave nodes whose gap is at most the distance, up
// to round-off, so that Initial contact refinements refine the zone before
// an impact across a gap of exactly that distance. Until 2026-11-30 the
// test was "below the distance": the two bars 2 g0 = 0.2 m apart with
// Distance = 0.2 m (the computed gap 0.2 + round-off) refined nothing before
// t = 0 (the program warned), and the contact began on cells one level
// coarser than Maximum level, with the contact force of the uniform mesh of
// that level. Checked: the bar against the wall (gap 0.1 m, Distance 0.1 m)
// and the two bars (Distance 0.2 m) refine as with a distance 10 % larger;
// a distance 10 % smaller refines nothing (40 cells along, 4 across: two
// cell sizes are below the gap). On 1 and 2 ranks (same output).

#include "tests.h"

namespace
{
  using namespace testing;

  // DoFs at step 0 of a run to the first step
  double
  initial_dofs(const std::string &scene, const double distance)
  {
    std::ostringstream s;
    s << std::setprecision(17) << scene
      << "subsection Mesh refinement\n"
         "  set Refinement interval = 4\n"
         "  set Maximum level = 2\n"
         "  set Initial contact refinements = 2\n"
         "  set Criteria = contact zone\n"
         "  subsection Contact zone\n"
         "    set Distance = "
      << distance
      << "\n"
         "  end\n"
         "end\n";
    return run(bar_prm(2, "N-CS++", 40, 0.0125, 0.0125, s.str()))
      .column("dofs")[0];
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  const std::vector<std::pair<std::string, std::string>> scenes = {
    {"bar against the wall, gap 0.1 m", ""},
    {"two bars, 0.2 m apart",
     scene_prm("two bars",
               "    set Cells across = 2\n"
               "    set Cells across body 2 = 3\n")}};
  const std::vector<double> gaps = {0.1, 0.2};
  for (unsigned int i = 0; i < scenes.size(); ++i)
    {
      const double equal   = initial_dofs(scenes[i].second, gaps[i]);
      const double larger  = initial_dofs(scenes[i].second, 1.1 * gaps[i]);
      const double smaller = initial_dofs(scenes[i].second, 0.9 * gaps[i]);
      log() << scenes[i].first << ": DoFs at t = 0 with Distance = gap "
            << equal << ", 1.1 gap " << larger << ", 0.9 gap " << smaller
            << "\n";
      log() << "  the gap equal to the distance is in the zone: "
            << check(equal == larger && equal > smaller) << "\n";
    }
}
