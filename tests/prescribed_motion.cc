// Dirichlet data that move (Scene/Gmsh/Prescribed displacements), against
// exact answers:
//
// 1. A bar [0, 10] x [0, 1] (E = 100, rho = 1, nu = 0: c = 10 m/s) pushed at
//    its left end with the velocity v = 0.01 m/s (u_x = v t on a roller,
//    from t = 0): it sends the wave of the 1D characteristics, of stress
//    rho c v, so that the end pushes with the force rho c v H = 0.1 N/m
//    (the time mean within 1 % until the wave reaches the far end) and the
//    work W_D = rho c v^2 H t splits into kinetic and elastic energy alike
//    (within 1 %). Each step (but those after a mesh change) changes the
//    momentum by exactly tau times the end's force (the stiffness moves no
//    momentum), and E + W_visc - W_D stays E(0) (both within 1e-10, the
//    solver's tolerance), for each of the three schemes, and on a mesh that
//    adapts (hanging nodes whose parents are on the moving end: without their
//    share of its motion the balance broke by 4e-1 of the energy).
//    A run resumed from a checkpoint repeats the uninterrupted one. The
//    punch of prm/punch.prm meets the block when its prescribed motion
//    closes the gap, and held, the support's force balances the contact
//    force (within 1 %).
// 2. The static problem: a column on rollers pressed down by d = 0.01 m at
//    its top (by 0.005 t at End time = 2 s: the static problem takes its
//    data at End time) is in uniaxial strain; linear elements give it
//    exactly, with the force (lambda + 2 mu) d / H per unit width on the
//    top.
// 3. Bad input is refused naming the entry.

#include <cmath>
#include <fstream>
#include <sstream>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;
  const auto prm = [](const std::string &mesh,
                      const std::string &entries,
                      const std::string &time_integration,
                      const std::string &more) {
    return "set Dimension = 2\nset Output directory = results-motion\n" +
           scene_prm("gmsh", "    set Mesh file = " + mesh + "\n" + entries) +
           more + "subsection Time integration\n" + time_integration +
           "end\nsubsection Output\n  set Write vtu = false\nend\n";
  };
  const std::string bar_material = "subsection Material\n"
                                   "  set Young's modulus = 100\n"
                                   "end\n";
  const std::string push         = "    set Dirichlet tags = 12: x\n"
                                   "    set Prescribed displacements = 12: v*t, 0\n"
                                   "    set Function constants = v = 0.01\n";
  write_block_msh("bar.msh", {{0, 10, 0, 1, 80, 4, 1, 10, 11, 12, 13}});
  const std::string adaptive = "subsection Mesh refinement\n"
                               "  set Refinement interval = 2\n"
                               "  set Maximum level = 1\n"
                               "  set Refine fraction = 0.03\n"
                               "  set Coarsen fraction = 0.3\n"
                               "  set Criteria = kelly velocity\n"
                               "end\n";
  // (adaptive: a shorter bar pushed more at its top, where the mesh
  // refines: hanging nodes whose parents are on the moving end)
  write_block_msh("short.msh", {{0, 2, 0, 1, 16, 8, 1, 10, 11, 12, 13}});
  for (const std::string scheme : {"N-CS++", "N-CI", "N-CS", "adaptive"})
    {
      const bool       adapts = scheme == "adaptive";
      const Statistics s =
        run(tight_steps() +
            prm(adapts ? "short.msh" : "bar.msh",
                adapts ? "    set Dirichlet tags = 12: x\n"
                         "    set Prescribed displacements = 12: "
                         "v*t*(1 + 3*y^2), 0\n"
                         "    set Function constants = v = 0.01\n" :
                         push,
                "  set Scheme = " + std::string(adapts ? "N-CS++" : scheme) +
                  "\n  set Time step = 0.0625\n  set End time = 0.75\n",
                bar_material + (adapts ? adaptive : "")));
      const auto time         = s.column("time"),
                 force        = s.column("prescribed_force_x");
      const auto   momentum   = s.column("momentum_x");
      const auto   balance    = s.column("energy_balance");
      const double tau        = 0.0625;
      double       mean_force = 0., momentum_error = 0., largest_balance = 0.,
             scale     = 0.;
      const auto cells = s.column("cells");
      for (unsigned int r = 1; r < time.size(); ++r)
        {
          mean_force += force[r] / (time.size() - 1);
          // (a step after a mesh change also has the transfer's change)
          if (cells[r] == cells[r - 1])
            momentum_error = std::max(momentum_error,
                                      std::abs(momentum[r] - momentum[r - 1] -
                                               tau * force[r]));
          largest_balance = std::max(largest_balance, std::abs(balance[r]));
          scale           = std::max(scale, s.column("energy_total")[r]);
        }
      const double t          = time.back();
      const double work       = s.column("work_prescribed").back();
      const double kinetic    = s.column("energy_kinetic").back();
      const double elastic    = s.column("energy_elastic").back();
      const double exact_work = 10. * 0.01 * 0.01 * t;
      const bool   exact      = momentum_error < 1e-10 * momentum.back() &&
                         largest_balance < 1e-10 * scale;
      if (adapts)
        log() << scheme << ": " << s.column("cells").front() << " to "
              << s.column("cells").back()
              << " cells; momentum = impulse and balance within 1e-10: "
              << check(s.column("cells").back() > s.column("cells").front() &&
                       exact)
              << "\n";
      else
        log() << scheme << ": mean force " << fmt(mean_force, 4)
              << " N/m (rho c v H = 0.1), W_D " << fmt(work, 4) << " J/m ("
              << fmt(exact_work, 4) << "), E_kin/E_el "
              << fmt(kinetic / elastic, 3)
              << "; momentum = impulse and balance within 1e-10: "
              << check(std::abs(mean_force / 0.1 - 1.) < 0.01 &&
                       std::abs(work / exact_work - 1.) < 0.01 &&
                       std::abs(kinetic / elastic - 1.) < 0.01 && exact)
              << "\n";
      if (!exact)
        log() << "  (momentum " << momentum_error << ", balance "
              << largest_balance << " of " << scale << ")\n";
    }

  // a run stopped at t = 0.375 s and resumed from its checkpoint gives the
  // uninterrupted run's statistics: the loads and the prescribed
  // displacements of the checkpoint's time, the work and the balance
  // carried on, the adapted mesh's prescribed nodes
  {
    const auto checkpointed = [&](const std::string &run_name,
                                  const std::string &end,
                                  const bool         resume) {
      std::string text =
        prm("short.msh",
            "    set Dirichlet tags = 12: x\n"
            "    set Prescribed displacements = 12: v*t*(1 + 3*y^2), 0\n"
            "    set Pressures = 11: 0.05*min(t/0.3, 1)\n"
            "    set Function constants = v = 0.01\n",
            "  set Time step = 0.0625\n  set End time = " + end + "\n",
            bar_material + adaptive +
              "subsection Checkpointing\n  set Interval in steps = 6\n"
              "  set Resume = " +
              (resume ? "true" : "false") + "\nend\n");
      const std::string directory = "results-motion\n";
      return text.replace(text.find(directory),
                          directory.size(),
                          "results-motion-" + run_name + "\n");
    };
    const Statistics full =
      run(tight_steps() + checkpointed("full", "0.75", false));
    run(tight_steps() + checkpointed("split", "0.375", false));
    const Statistics resumed =
      run(tight_steps() + checkpointed("split", "0.75", true));
    const auto [difference, worst] = statistics_difference(full, resumed);
    log() << "resumed at t = 0.375 s: the statistics agree to 1e-10: "
          << check(difference <= 1e-10 && full.has_column("work_prescribed") &&
                   full.has_column("work_load_change"))
          << "\n";
    if (difference > 1e-10)
      log() << "  (" << difference << " in " << worst << ")\n";
  }

  // prm/punch.prm: the punch's top moved down by d0 (1 - cos(pi t/T))/2
  // closes the 5 mm gap at t = T/3; held, the support's force on the punch
  // balances the contact force
  {
    std::ifstream     in(std::string(DYNCONTACT_PRM_DIR) + "/punch.prm");
    std::stringstream example;
    example << in.rdbuf();
    std::string text = example.str();
    text.replace(text.find("= meshes/"),
                 9,
                 "= " + std::string(DYNCONTACT_PRM_DIR) + "/meshes/");
    const Statistics s =
      run(tight_steps() + text +
          "set Output directory = results-punch\n"
          "subsection Output\n  set Write vtu = false\nend\n");
    const auto time           = s.column("time"),
               support        = s.column("prescribed_force_y");
    const auto   contact      = s.column("contact_force");
    double       mean_support = 0., mean_contact = 0.;
    unsigned int n_held = 0;
    for (unsigned int r = 0; r < time.size(); ++r)
      if (time[r] >= 0.11)
        {
          mean_support += support[r];
          mean_contact += contact[r];
          ++n_held;
        }
    mean_support /= n_held;
    mean_contact /= n_held;
    const double start = contact_interval(s).first;
    log() << "punch: contact from t = " << fmt(start, 4)
          << " s (T/3 = 0.0333 s), held: support force " << fmt(mean_support)
          << " N/m, contact force " << fmt(mean_contact)
          << " N/m, largest penetration below 1e-12 m: "
          << check(std::abs(start - 0.1 / 3.) <= 0.0005 &&
                   std::abs(mean_support + mean_contact) <
                     0.01 * mean_contact &&
                   max_of(s.column("max_penetration")) < 1e-12)
          << "\n";
  }

  // 2. the static column pressed down at its top
  write_block_msh("column.msh", {{0, 1, 0, 2, 4, 8, 1, 10, 11, 12, 13}});
  {
    const Statistics s =
      run(tight_steps() +
          prm("column.msh",
              "    set Dirichlet tags = 10: y, 11: y, 12: x, 13: x\n"
              "    set Prescribed displacements = 11: 0, -0.005*t\n",
              "  set Scheme = static\n  set End time = 2\n",
              "subsection Material\n  set Young's modulus = 100\n"
              "  set Poisson's ratio = 0.3\nend\n"));
    const double lambda = 100. * 0.3 / (1.3 * 0.4), mu = 100. / 2.6;
    const double exact = -(lambda + 2. * mu) * 0.01 / 2.;
    const double force = s.column("prescribed_force_y").back();
    const double mean  = s.column("mean_displacement_y").back();
    log() << "static column: force on the top " << fmt(force, 6) << " N/m ("
          << fmt(exact, 6) << "), mean u_y " << fmt(mean, 6) << " m (-0.005): "
          << check(std::abs(force / exact - 1.) < 1e-9 &&
                   std::abs(mean + 0.005) < 1e-11)
          << "\n";
  }

  // 3. bad input
  const std::string dynamic =
    "  set Time step = 0.0625\n  set End time = 0.125\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"    set Dirichlet tags = 12: x\n"
     "    set Prescribed displacements = 13: t, 0\n",
     "tag 13 is not in Dirichlet tags"},
    {"    set Dirichlet tags = 12: x\n"
     "    set Prescribed displacements = 12: t, t\n",
     "component 2 ('t') is not fixed by Dirichlet tags"},
    {"    set Dirichlet tags = 12: x\n"
     "    set Prescribed displacements = 12: t\n",
     "a 2D mesh needs 2"},
    {"    set Dirichlet tags = 12: x\n"
     "    set Prescribed displacements = 12: t*, 0\n",
     "Scene/Gmsh/Prescribed displacements (tag 12)"},
    {"    set Dirichlet tags = 12: x\n"
     "    set Prescribed displacements = 12: 1/(t - 0.0625), 0\n",
     "The prescribed displacement of tag 12 is inf m"},
    {"    set Dirichlet tags = 12: x\n"
     "    set Pressures = 11: 1e200*t\n",
     "A load given as a function is 6.25e+198 (not finite, or beyond 1e15 "
     "in magnitude) at t = 0.0625 s: the pressure of tag 11"},
    {"    set Dirichlet tags = 12: x\n"
     "    set Body force = 0; sqrt(t - 0.1)\n",
     "(not finite, or beyond 1e15 in magnitude) at t = 0 s: the body force "
     "of body 1"},
    // a slave node of the obstacle that the support moves along the normal
    {"    set Dirichlet tags = 12\n"
     "    set Prescribed displacements = 12: 0, -0.5*t\n"
     "    set Bodies = 1\n    set Contact tags = 10\n"
     "    set Contact pairs = 1 : obstacle\n"
     "    set Obstacle point = 0, -0.01\n    set Obstacle normal = 0, 1\n",
     "A contact surface shares nodes with a boundary whose displacement is "
     "prescribed"}};
  for (const auto &[entries, fragment] : cases)
    {
      const std::string message =
        error_of(prm("bar.msh", entries, dynamic, bar_material));
      log() << "refused: " << check(message.find(fragment) != std::string::npos)
            << "\n";
      if (message.find(fragment) == std::string::npos)
        log() << "  (" << message << ")\n";
    }
  // a master surface whose corner moves with the prescribed data
  write_block_msh("two.msh",
                  {{0, 1, 0, 0.5, 4, 2, 1, 10, 11, 12},
                   {0, 1, 0.52, 1.02, 4, 2, 2, 20, 21}});
  log() << "refused (a contact row on a moving node): "
        << check(error_of(prm("two.msh",
                              "    set Bodies = 1; 2\n"
                              "    set Contact tags = 11; 20\n"
                              "    set Contact pairs = 2 : 1 : 0.1\n"
                              "    set Dirichlet tags = 10, 12: y\n"
                              "    set Prescribed displacements = 12: 0, "
                              "0.01*t\n",
                              dynamic,
                              bar_material))
                   .find("A contact surface shares nodes with a boundary "
                         "whose displacement is prescribed") !=
                 std::string::npos)
        << "\n";
  // a motion defined for t >= 0 only: its initial velocity is taken
  // after t = 0
  {
    const Statistics s =
      run(tight_steps() +
          prm("bar.msh",
              "    set Dirichlet tags = 12: x\n"
              "    set Prescribed displacements = 12: 0.01*t^1.5, 0\n",
              dynamic,
              bar_material));
    // (the one-sided difference quotient of t^1.5 at 0 is of the order of
    // sqrt(delta), here 5e-5 m/s on the end's nodes of mass 0.0625)
    const double p0 = s.column("momentum_x")[0];
    log() << "g = 0.01 t^1.5 (undefined for t < 0) starts near rest: "
          << check(std::isfinite(s.column("energy_total").back()) &&
                   std::abs(p0) < 1e-5)
          << "\n";
  }
  log() << "refused (consistent mass): "
        << check(error_of(prm("bar.msh",
                              push,
                              dynamic + "  set Mass matrix = consistent\n",
                              bar_material))
                   .find("need 'Time integration/Mass matrix = lumped'") !=
                 std::string::npos)
        << "\n";
}
