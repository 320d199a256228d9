// Persistency (eq. 19): the largest normal velocity |c_p . udot| over the
// rows active in the displacement step; N-CS++ makes it zero with a lumped
// mass (a consistent or blended one couples the projection's rows, which
// may release a row of the step: a small normal velocity remains).

#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/integrators.h>

#include <cmath>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class Persistency : public Interface<dim>
    {
    public:
      bool
      applies() const override
      {
        return this->get_scene().has_contact();
      }

      std::vector<std::string>
      columns() const override
      {
        return {"max_active_normal_velocity"};
      }

      void
      execute(std::vector<double> &row) override
      {
        const StepReport &report  = this->get_step_report();
        double            largest = 0.;
        const auto        normal_velocity =
          this->get_contact().get_row_operator().apply(this->get_velocity());
        for (unsigned int p = 0; p < normal_velocity.size(); ++p)
          if (report.active[p])
            largest = std::max(largest, std::abs(normal_velocity[p]));
        row.push_back(
          Utilities::MPI::max(largest, this->get_mpi_communicator()));
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(Persistency,
                                      "persistency",
                                      "normal velocity at active nodes "
                                      "(eq. 19)")
  } // namespace Postprocess
} // namespace dyncontact
