// Linear momentum (Theorem 3.1): sum of M udot over the DoFs of each
// displacement component, for all bodies, and for each body after the first
// alone (the first's is the total minus these). Mean displacement: the
// mass-weighted mean of u per component and body, sum of M u over sum of M 1,
// the displacement of the body's centre of mass (the position error of a body
// beside its energy-norm error).

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>

namespace dyncontact
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * Sums of (M x)_i over each body's DoFs of each component, over all
       * ranks: entry 3 b + d for body b and component d.
       */
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
          sums[3 * (slots[k] / dim) + slots[k] % dim] += values[k];
        Utilities::MPI::sum(sums, communicator, sums);
        return sums;
      }
    } // namespace



    template <int dim>
    class Momentum : public Interface<dim>
    {
    public:
      std::vector<std::string>
      columns() const override
      {
        std::vector<std::string> names = {"momentum_x",
                                          "momentum_y",
                                          "momentum_z"};
        for (unsigned int b = 2; b <= this->get_scene().n_bodies(); ++b)
          for (const std::string name :
               {"momentum_x", "momentum_y", "momentum_z"})
            names.push_back(name + "_body" + std::to_string(b));
        return names;
      }

      void
      execute(std::vector<double> &row) override
      {
        const unsigned int        n_bodies = this->get_scene().n_bodies();
        const std::vector<double> body_momentum =
          body_sums(this->get_system(),
                    this->get_velocity(),
                    n_bodies,
                    this->get_mpi_communicator());
        std::vector<double> momentum(3, 0.);
        for (unsigned int b = 0; b < n_bodies; ++b)
          for (unsigned int d = 0; d < 3; ++d)
            momentum[d] += body_momentum[3 * b + d];
        row.insert(row.end(), momentum.begin(), momentum.end());
        row.insert(row.end(), body_momentum.begin() + 3, body_momentum.end());
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(Momentum,
                                      "momentum",
                                      "linear momentum, total and of each "
                                      "body after the first (Theorem 3.1)")



    template <int dim>
    class MeanDisplacement : public Interface<dim>
    {
    public:
      /// One body: mean_displacement_x, _y, _z; two bodies: the same names
      /// with _body1 and _body2 (the centre of mass of both is of no use).
      std::vector<std::string>
      columns() const override
      {
        const unsigned int       n_bodies = this->get_scene().n_bodies();
        std::vector<std::string> names;
        for (unsigned int b = 0; b < n_bodies; ++b)
          for (const char *d : {"_x", "_y", "_z"})
            names.push_back(
              std::string("mean_displacement") + d +
              (n_bodies == 1 ? "" : "_body" + std::to_string(b + 1)));
        return names;
      }

      void
      execute(std::vector<double> &row) override
      {
        const SemiDiscreteSystem<dim> &system   = this->get_system();
        const unsigned int             n_bodies = this->get_scene().n_bodies();
        const VectorType              &u        = this->get_solution();
        // M is symmetric and couples neither components nor bodies: the
        // sum of M u over a body's component is that of m_i u_i with the
        // row sums m = M 1, and its mass that of m_i (one product)
        VectorType ones(u), m;
        ones = 1.;
        system.matrices().mass_vmult(m, ones);
        std::vector<double> sums(6 * n_bodies, 0.); // M u, then the masses
        const std::vector<unsigned char> &slots = system.get_owned_dof_slots();
        const double *m_values = m.begin(), *u_values = u.begin();
        for (std::size_t k = 0; k < slots.size(); ++k)
          {
            const unsigned int slot = 3 * (slots[k] / dim) + slots[k] % dim;
            sums[slot] += m_values[k] * u_values[k];
            sums[3 * n_bodies + slot] += m_values[k];
          }
        Utilities::MPI::sum(sums, this->get_mpi_communicator(), sums);
        for (unsigned int k = 0; k < 3 * n_bodies; ++k)
          row.push_back(sums[3 * n_bodies + k] > 0. ?
                          sums[k] / sums[3 * n_bodies + k] :
                          0.);
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(MeanDisplacement,
                                      "mean displacement",
                                      "mass-weighted mean displacement of "
                                      "each body (of its centre of mass)")
  } // namespace Postprocess
} // namespace dyncontact
