// The stiff and extreme suite (prm/extreme/*.prm: stiffness contrast 1e4 and
// 1e6, nu = 0.49, heavy viscosity, v0 tau of a hundred cells, tau longer
// than the contact, tau = 1e-6, cells of aspect ratio 50, grazing contact,
// bodies touching at t = 0, an initially penetrating start projected onto
// K_h), each with N-CI, N-CS and N-CS++: the run completes (the active set
// converges in every step, nothing is NaN or Inf), E_total + dissipation
// never increases for N-CI and N-CS++ (Theorem 3.2; to 1e-9 of the largest
// energy), and nothing penetrates beyond 1e-9 m.

#include <filesystem>
#include <set>

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  std::set<std::filesystem::path> files;
  for (const auto &entry : std::filesystem::directory_iterator(
         std::string(DYNCONTACT_PRM_DIR) + "/extreme"))
    if (entry.path().extension() == ".prm")
      files.insert(entry.path());

  for (const auto &file : files)
    for (const std::string scheme : {"N-CI", "N-CS", "N-CS++"})
      {
        std::ifstream     in(file);
        std::stringstream text;
        text << in.rdbuf() << "\nset Output directory = results-"
             << file.stem().string() << "-" << scheme
             << "\nsubsection Time integration\n  set Scheme = " << scheme
             << "\nend\n";
        bool       completed = true;
        Statistics s;
        try
          {
            s = dyncontact::run_simulation(text.str(),
                                           MPI_COMM_WORLD,
                                           file.string());
          }
        catch (const std::exception &e)
          {
            completed = false;
            std::cout << e.what() << std::endl;
          }
        log() << file.stem().string() << ", " << scheme
              << ": completes (active set converged, finite): "
              << check(completed);
        if (completed)
          {
            double scale = 0.;
            for (const double e : s.column("energy_total"))
              scale = std::max(scale, std::abs(e));
            if (scheme != "N-CS")
              log() << ", energy non-increasing: "
                    << check(max_energy_increase(s) <= 1e-9 * scale);
            log() << ", no penetration: "
                  << check(max_of(s.column("max_penetration")) <= 1e-9);
          }
        log() << "\n";
      }
}
