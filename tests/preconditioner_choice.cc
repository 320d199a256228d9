// 'Contact solver/Preconditioner = automatic' takes Jacobi where a bound of
// the condition number of the step matrix scaled by its diagonal is at most
// 100, and AMG where not (and, as preconditioner_choice.mpirun=2, the same
// on two ranks). Checked on the 2D bar impact:
// - at tau = h/2c the bound is 11/8 (at a corner node S_ii/M_ii = 9/8 and
//   Gershgorin's sum_j |S_ij|/S_ii = 11/9, by hand for Q1 with nu = 0), and
//   Jacobi is taken; at tau c/h = 20 the bound exceeds 100 and AMG is taken;
// - Jacobi and AMG give the same energies, contact forces and pressures to
//   the CG tolerance (a preconditioner that wrote into constrained entries
//   would not);
// - at fixed tau c/h = 1/2 the CG iterations of a contact step with Jacobi
//   do not grow with the mesh (40 to 320 cells along), which is why Jacobi
//   is the right choice there.

#include "tests.h"

namespace
{
  /// The line "preconditioner: ..." of the run's summary.txt.
  std::string
  preconditioner_line(const std::string &directory)
  {
    std::ifstream in(directory + "/summary.txt");
    for (std::string line; std::getline(in, line);)
      if (line.rfind("preconditioner: ", 0) == 0)
        return line.substr(16);
    return "(no preconditioner line)";
  }

  /// The number after "at most " in @p line (nan if none).
  double
  bound_in(const std::string &line)
  {
    const auto at = line.find("at most ");
    return at == std::string::npos ? std::nan("") :
                                     std::stod(line.substr(at + 8));
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  // the choice and its bound
  {
    const unsigned int cells = 40;
    const double       h     = 1. / cells;
    for (const double tau_c_h : {0.5, 20.})
      {
        const std::string directory =
          "output-choice-" + std::to_string(int(10 * tau_c_h));
        run(tight_steps() +
            bar_prm(2,
                    "N-CS++",
                    cells,
                    tau_c_h * h,
                    0.2,
                    "set Output directory = " + directory + "\n"));
        const std::string line  = preconditioner_line(directory);
        const double      bound = bound_in(line);
        log() << "tau c/h = " << tau_c_h << ": " << line << "\n";
        if (tau_c_h == 0.5)
          log() << "  Jacobi, bound 11/8: "
                << check(line.rfind("Jacobi", 0) == 0 &&
                         std::abs(bound - 1.375) < 1e-2)
                << "\n";
        else
          log() << "  AMG, bound above 100: "
                << check(line.rfind("AMG", 0) == 0 && bound > 100.) << "\n";
      }
  }

  // the same solution with either preconditioner
  {
    const unsigned int      cells = 80;
    const double            tau   = 0.5 / cells;
    std::vector<Statistics> runs;
    for (const std::string preconditioner : {"Jacobi", "AMG"})
      runs.push_back(
        run(tight_steps() +
            bar_prm(2,
                    "N-CS++",
                    cells,
                    tau,
                    2.5,
                    "set Output directory = output-" + preconditioner +
                      "\nsubsection Contact solver\n"
                      "  set Preconditioner = " +
                      preconditioner + "\nend\n")));
    double difference = 0.;
    for (const std::string column :
         {"energy_total", "contact_force", "max_contact_pressure"})
      {
        const auto   a = runs[0].column(column), b = runs[1].column(column);
        const double scale = std::max(max_of(a), 1e-300);
        for (unsigned int i = 0; i < a.size(); ++i)
          difference = std::max(difference, std::abs(a[i] - b[i]) / scale);
      }
    // (the solutions agree to CG's relative tolerance 1e-12; the contact
    // force, a residual times 2/tau^2, to about 2e-8 of its largest value)
    log() << "Jacobi and AMG: same energies, contact forces and pressures "
             "(1e-7): "
          << check(difference < 1e-7) << "\n";
  }

  // Jacobi's iterations per contact step do not grow with the mesh
  {
    std::vector<double> largest;
    for (const unsigned int cells : {40u, 80u, 160u, 320u})
      {
        const double     tau = 0.5 / cells;
        const Statistics s =
          run(tight_steps() + bar_prm(2,
                                      "N-CS++",
                                      cells,
                                      tau,
                                      0.4,
                                      "subsection Postprocess\n"
                                      "  subsection Error energy norm\n"
                                      "    set Interval = output times\n"
                                      "  end\nend\n"));
        const auto cg     = s.column("linear_iterations"),
                   active = s.column("active_nodes");
        double most       = 0.;
        for (unsigned int i = 0; i < cg.size(); ++i)
          if (active[i] > 0)
            most = std::max(most, cg[i]);
        largest.push_back(most);
      }
    log() << "most CG iterations in a contact step, 40 to 320 cells along, "
             "at most 30 and growing by at most 20%: "
          << check(max_of(largest) <= 30. &&
                   largest.back() <= 1.2 * largest.front())
          << "\n";
  }
}
