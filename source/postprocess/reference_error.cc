// The error in the physical energy norm against the states of a reference
// run (the same mesh or a refinement of it, any tau) at the reference times,
// NaN in between.

#include <dyncontact/output/reference_states.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/time_stepping/simulation_control.h>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class ReferenceError : public Interface<dim>
    {
    public:
      bool
      applies() const override
      {
        return this->get_reference_states().compares();
      }

      std::string
      summary(const Statistics &s, const SummaryInput &) const override
      {
        return error_summary(s, "error_reference");
      }


      std::vector<std::string>
      columns() const override
      {
        return {"error_reference"};
      }

      bool
      sampled() const override
      {
        return true;
      }

      /// At the reference times.
      bool
      due() const override
      {
        return this->get_reference_states().at_reference_time(
          this->get_control().get_time());
      }

      bool
      is_norm() const override
      {
        return true;
      }

      /// (apart from the other norms: a study counts it as its overhead)
      std::string
      timer_section() const override
      {
        return "reference states";
      }

      void
      execute(std::vector<double> &row) override
      {
        row.push_back(
          this->get_reference_states().error(this->get_control().get_time()));
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(ReferenceError,
                                      "reference error",
                                      "energy-norm error against reference "
                                      "states")
  } // namespace Postprocess
} // namespace dyncontact
