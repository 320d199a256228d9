// The bar impact rotated by 30 degrees about the z axis (2D) and 3D: the
// wall normal is no coordinate axis, so every contact row couples two
// components and the eliminated component is not the normal one. With
// lumped mass and nu = 0 the rotated problem is the same problem: energies,
// contact force and the energy-norm error agree with the unrotated run to
// solver tolerance.

#include "tests.h"

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  for (const unsigned int dim : {2u, 3u})
    for (const std::string scheme : {"N-CI", "N-CS++"})
      {
        const unsigned int cells = 20;
        const double       tau   = 1. / cells / 2.;
        const Statistics   plain =
          run(tight_steps() + bar_prm(dim, scheme, cells, tau, 2.5));
        const Statistics rotated =
          run(tight_steps() +
              bar_prm(dim,
                      scheme,
                      cells,
                      tau,
                      2.5,
                      scene_entries("Bar impact",
                                    "    set Rotation angle = 30\n")));
        double difference = 0., scale = 0.;
        for (const std::string column : {"energy_total",
                                         "contact_force",
                                         "error_energy_norm",
                                         "max_contact_pressure"})
          {
            const auto a = plain.column(column), b = rotated.column(column);
            for (unsigned int i = 0; i < a.size(); ++i)
              {
                difference = std::max(difference, std::abs(a[i] - b[i]));
                scale      = std::max(scale, std::abs(a[i]));
              }
          }
        log() << dim << "D, " << scheme
              << ": rotated run agrees with the plain one to 1e-8: "
              << check(difference <= 1e-8 * scale) << "\n";
        log() << "  active rows in contact: "
              << max_of(rotated.column("active_nodes")) << "\n";
      }
}
