// Reference states: a reference run (same mesh, much smaller time step)
// writes u and udot at fixed times; another run reads them at the same times
// and computes the error in the physical energy norm on the same mesh,
// ||(e, edot)||_E^2 = 1/2 edot^T M edot + 1/2 e^T A e (eqs. 22-24, without
// the viscous time integral).

#include <deal.II/base/utilities.h>

#include <dyncontact/simulator.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace dyncontact
{
  namespace
  {
    std::string
    state_file(const std::string &directory,
               const unsigned int index,
               const unsigned int rank)
    {
      return directory + "/state_" + Utilities::int_to_string(index, 5) + "." +
             std::to_string(rank) + ".bin";
    }
  } // namespace



  template <int dim>
  double
  Simulator<dim>::process_reference_state(const double time)
  {
    if (!parameters.write_reference && !parameters.compare_reference)
      return std::nan("");
    // only at (numerically) multiples of the interval
    const double       k     = time / parameters.reference_interval;
    const unsigned int index = std::lround(k);
    if (std::abs(k - index) > 1e-6)
      return std::nan("");

    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const std::string  file =
      state_file(parameters.reference_directory, index, rank);
    if (parameters.write_reference)
      {
        if (rank == 0)
          std::filesystem::create_directories(parameters.reference_directory);
        MPI_Barrier(comm);
        std::ofstream       out(file, std::ios::binary);
        const unsigned long n     = locally_owned.n_elements();
        const unsigned long total = dof_handler.n_dofs();
        out.write(reinterpret_cast<const char *>(&total), sizeof(total));
        out.write(reinterpret_cast<const char *>(&n), sizeof(n));
        for (const auto i : locally_owned)
          {
            const unsigned long index_    = i;
            const double        values[2] = {u(i), udot(i)};
            out.write(reinterpret_cast<const char *>(&index_), sizeof(index_));
            out.write(reinterpret_cast<const char *>(values), sizeof(values));
          }
        AssertThrow(out.good(),
                    ExcMessage("Cannot write the reference state '" + file +
                               "'."));
        return std::nan("");
      }

    std::ifstream in(file, std::ios::binary);
    AssertThrow(in.good(),
                ExcMessage(
                  "Reference solution: there is no reference state '" + file +
                  "' (a reference run on the same mesh and number of "
                  "MPI ranks, with the same Interval, must write it)."));
    unsigned long total = 0, n = 0;
    in.read(reinterpret_cast<char *>(&total), sizeof(total));
    in.read(reinterpret_cast<char *>(&n), sizeof(n));
    AssertThrow(total == dof_handler.n_dofs() &&
                  n == locally_owned.n_elements(),
                ExcMessage("Reference solution: the state '" + file +
                           "' belongs to a different mesh or partition (" +
                           std::to_string(total) + " DoFs, here " +
                           std::to_string(dof_handler.n_dofs()) + ")."));
    VectorType e(u), edot(udot);
    for (unsigned long j = 0; j < n; ++j)
      {
        unsigned long index_;
        double        values[2];
        in.read(reinterpret_cast<char *>(&index_), sizeof(index_));
        in.read(reinterpret_cast<char *>(values), sizeof(values));
        AssertThrow(in.good() && locally_owned.is_element(index_),
                    ExcMessage("Reference solution: the state '" + file +
                               "' does not match this mesh's partition."));
        e(index_) -= values[0];
        edot(index_) -= values[1];
      }
    e.compress(VectorOperation::insert);
    edot.compress(VectorOperation::insert);
    VectorType tmp(u);
    mass_matrix.vmult(tmp, edot);
    double error2 = 0.5 * (tmp * edot);
    stiffness_matrix.vmult(tmp, e);
    error2 += 0.5 * (tmp * e);
    return std::sqrt(std::max(error2, 0.));
  }

  template double
  Simulator<2>::process_reference_state(const double);
  template double
  Simulator<3>::process_reference_state(const double);
} // namespace dyncontact
