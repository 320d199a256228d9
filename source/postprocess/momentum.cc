// Linear momentum (Theorem 3.1): sum of M udot over the DoFs of each
// displacement component, for all bodies, and for each body after the first
// alone (the first's is the total minus these). Mean displacement: the
// mass-weighted mean of u per component and body, sum of M u over sum of M 1,
// the displacement of the body's centre of mass (the position error of a body
// beside its energy-norm error).

#include <dyncontact/discretization/body_sums.h>
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
        const std::vector<double> means =
          body_mean_displacements(this->get_system(),
                                  this->get_solution(),
                                  this->get_scene().n_bodies(),
                                  this->get_mpi_communicator());
        row.insert(row.end(), means.begin(), means.end());
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(MeanDisplacement,
                                      "mean displacement",
                                      "mass-weighted mean displacement of "
                                      "each body (of its centre of mass)")
  } // namespace Postprocess
} // namespace dyncontact
