// Linear momentum (Theorem 3.1): sum of M udot over the DoFs of each
// displacement component, for all bodies, and for the second body alone in
// two-body scenes.

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>

namespace dyncontact
{
  namespace Postprocess
  {
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
        if (this->get_scene().n_bodies() == 2)
          for (const std::string name :
               {"momentum_x_body2", "momentum_y_body2", "momentum_z_body2"})
            names.push_back(name);
        return names;
      }

      void
      execute(std::vector<double> &row) override
      {
        const SemiDiscreteSystem<dim> &system   = this->get_system();
        const unsigned int             n_bodies = this->get_scene().n_bodies();
        VectorType                     M_udot;
        system.matrices().mass_vmult(M_udot, this->get_velocity());

        // sums of (M udot)_i over each body's DoFs of each component, in
        // the order of the DoF numbers
        std::vector<double>               body_momentum(3 * n_bodies, 0.);
        const std::vector<unsigned char> &slots  = system.get_owned_dof_slots();
        const double                     *values = M_udot.begin();
        for (std::size_t k = 0; k < slots.size(); ++k)
          body_momentum[3 * (slots[k] / dim) + slots[k] % dim] += values[k];
        Utilities::MPI::sum(body_momentum,
                            this->get_mpi_communicator(),
                            body_momentum);
        std::vector<double> momentum(3, 0.);
        for (unsigned int b = 0; b < n_bodies; ++b)
          for (unsigned int d = 0; d < 3; ++d)
            momentum[d] += body_momentum[3 * b + d];
        row.insert(row.end(), momentum.begin(), momentum.end());
        if (n_bodies == 2)
          row.insert(row.end(), body_momentum.begin() + 3, body_momentum.end());
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(Momentum,
                                      "momentum",
                                      20,
                                      "linear momentum, total and of the "
                                      "second body (Theorem 3.1)")
  } // namespace Postprocess
} // namespace dyncontact
