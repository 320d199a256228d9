#include <dyncontact/discretization/body_sums.h>
#include <dyncontact/discretization/semi_discrete_system.h>

#include <algorithm>
#include <cmath>

// Sums over each body of M x: momentum and the mean displacement (the
// momentum and mean displacement postprocessors, and the change of both
// at a mesh transfer).

namespace dyncontact
{
  namespace
  {
    /// The entry 3 b + d of the sums for a DoF's slot b dim + d (body b,
    /// component d; SemiDiscreteSystem::get_owned_dof_slots()).
    template <int dim>
    unsigned int
    sum_entry(const unsigned char slot)
    {
      return 3 * (slot / dim) + slot % dim;
    }
  } // namespace



  template <int dim>
  std::vector<double>
  body_sums(const SemiDiscreteSystem<dim> &system,
            const VectorType              &x,
            const unsigned int             n_bodies,
            const MPI_Comm                 communicator)
  {
    VectorType M_x;
    system.matrices().mass_vmult(M_x, x);
    std::vector<double>               sums(3 * n_bodies, 0.);
    const std::vector<unsigned char> &slots  = system.get_owned_dof_slots();
    const double                     *values = M_x.begin();
    for (std::size_t k = 0; k < slots.size(); ++k)
      sums[sum_entry<dim>(slots[k])] += values[k];
    Utilities::MPI::sum(sums, communicator, sums);
    return sums;
  }



  template <int dim>
  std::vector<std::vector<double>>
  body_means(const SemiDiscreteSystem<dim>         &system,
             const std::vector<const VectorType *> &xs,
             const unsigned int                     n_bodies,
             const MPI_Comm                         communicator)
  {
    // M is symmetric and couples neither components nor bodies: the sum of
    // M x over a body's component is that of m_i x_i with the row sums
    // m = M 1, and its mass that of m_i (one product for all of @p xs)
    VectorType ones(*xs[0]), m;
    ones = 1.;
    system.matrices().mass_vmult(m, ones);
    const unsigned int n = 3 * n_bodies;
    // the sums of M x for each x, then the masses
    std::vector<double>               sums((xs.size() + 1) * n, 0.);
    const std::vector<unsigned char> &slots    = system.get_owned_dof_slots();
    const double                     *m_values = m.begin();
    for (std::size_t k = 0; k < slots.size(); ++k)
      {
        const unsigned int slot = sum_entry<dim>(slots[k]);
        for (std::size_t v = 0; v < xs.size(); ++v)
          sums[v * n + slot] += m_values[k] * xs[v]->begin()[k];
        sums[xs.size() * n + slot] += m_values[k];
      }
    Utilities::MPI::sum(sums, communicator, sums);
    std::vector<std::vector<double>> means(xs.size(),
                                           std::vector<double>(n, 0.));
    for (std::size_t v = 0; v < xs.size(); ++v)
      for (unsigned int k = 0; k < n; ++k)
        means[v][k] = sums[xs.size() * n + k] > 0. ?
                        sums[v * n + k] / sums[xs.size() * n + k] :
                        0.;
    return means;
  }



  template <int dim>
  std::vector<double>
  body_mean_displacements(const SemiDiscreteSystem<dim> &system,
                          const VectorType              &u,
                          const unsigned int             n_bodies,
                          const MPI_Comm                 communicator)
  {
    return body_means(system, {&u}, n_bodies, communicator)[0];
  }



  template <int dim>
  void
  shift_body_means(const SemiDiscreteSystem<dim>          &system,
                   const std::vector<VectorType *>        &xs,
                   const std::vector<std::vector<double>> &means,
                   const unsigned int                      n_bodies,
                   const MPI_Comm                          communicator)
  {
    const std::vector<const VectorType *>  read(xs.begin(), xs.end());
    const std::vector<std::vector<double>> now =
      body_means(system, read, n_bodies, communicator);
    // the slots with a Dirichlet DoF (a constrained DoF without entries;
    // the program's Dirichlet data hold components along the axes, so that
    // a translation along a free axis keeps them: a slanted constraint
    // u . n = 0 has entries and would need the shift along its tangent)
    std::vector<double>               held(3 * n_bodies, 0.);
    const std::vector<unsigned char> &slots = system.get_owned_dof_slots();
    const IndexSet                   &owned = system.locally_owned_dofs();
    const auto                       &constraints = system.get_constraints();
    for (std::size_t k = 0; k < slots.size(); ++k)
      {
        const auto *entries =
          constraints.get_constraint_entries(owned.nth_index_in_set(k));
        if (entries != nullptr && entries->empty())
          held[sum_entry<dim>(slots[k])] = 1.;
      }
    Utilities::MPI::max(held, communicator, held);
    for (std::size_t v = 0; v < xs.size(); ++v)
      {
        double *values = xs[v]->begin();
        for (std::size_t k = 0; k < slots.size(); ++k)
          {
            const unsigned int slot = sum_entry<dim>(slots[k]);
            if (held[slot] == 0.)
              values[k] += means[v][slot] - now[v][slot];
          }
      }
  }



  double
  largest_body_change(const std::vector<double> &a,
                      const std::vector<double> &b)
  {
    double largest = 0.;
    for (std::size_t k = 0; k + 2 < a.size() && k + 2 < b.size(); k += 3)
      largest = std::max(largest,
                         std::sqrt(std::pow(a[k] - b[k], 2) +
                                   std::pow(a[k + 1] - b[k + 1], 2) +
                                   std::pow(a[k + 2] - b[k + 2], 2)));
    return largest;
  }



#define DYNCONTACT_INSTANTIATE(dim)                                        \
  template std::vector<double> body_sums(const SemiDiscreteSystem<dim> &,  \
                                         const VectorType &,               \
                                         const unsigned int,               \
                                         const MPI_Comm);                  \
  template std::vector<double> body_mean_displacements(                    \
    const SemiDiscreteSystem<dim> &,                                       \
    const VectorType &,                                                    \
    const unsigned int,                                                    \
    const MPI_Comm);                                                       \
  template std::vector<std::vector<double>> body_means(                    \
    const SemiDiscreteSystem<dim> &,                                       \
    const std::vector<const VectorType *> &,                               \
    const unsigned int,                                                    \
    const MPI_Comm);                                                       \
  template void shift_body_means(const SemiDiscreteSystem<dim> &,          \
                                 const std::vector<VectorType *> &,        \
                                 const std::vector<std::vector<double>> &, \
                                 const unsigned int,                       \
                                 const MPI_Comm);
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
