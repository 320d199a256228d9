// The critical set Gamma*_{h,C} (eq. 40): the rows where the L2 projection
// (12f; for N-CS its predictor's) is active but the displacement step is
// not; its measure in this step and the running sum (Assumption 4.7), and
// the size of the velocity correction the projection makes.

#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/integrators.h>

#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class CriticalSet : public Interface<dim>
    {
    public:
      bool
      applies() const override
      {
        return this->get_scene().has_contact();
      }

      /// The sum of meas Gamma* over the steps (Assumption 4.7).
      std::string
      summary(const Statistics &s, const SummaryInput &input) const override
      {
        if (input.is_static)
          return "";
        std::ostringstream out;
        out << std::setprecision(6) << "sum of meas Gamma*: "
            << s.column("critical_measure_sum")[s.rows.size() - 1]
            << " (eq. 40, summed over the steps)\n";
        return out.str();
      }


      std::vector<std::string>
      columns() const override
      {
        return {"critical_measure",
                "critical_measure_sum",
                "velocity_correction"};
      }

      void
      execute(std::vector<double> &row) override
      {
        const ContactRows &rows    = this->get_contact().get_rows();
        const StepReport  &report  = this->get_step_report();
        double             measure = 0.;
        for (unsigned int p = 0; p < rows.size(); ++p)
          if (report.critical[p])
            measure += rows.rows[p].weight;
        measure = Utilities::MPI::sum(measure, this->get_mpi_communicator());
        sum += measure;
        row.insert(row.end(), {measure, sum, report.velocity_correction});
      }

      void
      save(std::map<std::string, std::string> &state) const override
      {
        std::ostringstream s;
        s << std::setprecision(17) << sum;
        state["critical_measure_sum"] = s.str();
      }

      void
      load(const std::map<std::string, std::string> &state) override
      {
        sum = std::stod(state.at("critical_measure_sum"));
      }

    private:
      double sum = 0.;
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(CriticalSet,
                                      "critical set",
                                      "meas Gamma* (eq. 40), its sum "
                                      "(Assumption 4.7), velocity correction")
  } // namespace Postprocess
} // namespace dyncontact
