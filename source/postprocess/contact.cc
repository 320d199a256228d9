// The contact of the displacement step: active rows and their measure, the
// contact force 2/tau^2 mu_p (static: mu_p) summed, the largest nodal
// pressure, and the largest violation of C u <= g after the step.

#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/integrators.h>

#include <algorithm>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class Contact : public Interface<dim>
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
        return {"active_nodes",
                "active_measure",
                "contact_force",
                "max_contact_pressure",
                "max_penetration"};
      }

      void
      execute(std::vector<double> &row) override
      {
        const ContactRows &rows   = this->get_contact().get_rows();
        const StepReport  &report = this->get_step_report();
        const double       factor = this->get_integrator().force_factor();
        double n_active = 0., measure = 0., force = 0., max_pressure = 0.;
        for (unsigned int p = 0; p < rows.size(); ++p)
          if (report.active[p])
            {
              n_active += 1.;
              measure += rows.rows[p].weight;
              const double f_p = factor * report.multipliers[p];
              force += f_p;
              max_pressure = std::max(max_pressure, f_p / rows.rows[p].weight);
            }
        double max_penetration = 0.;
        if (!rows.empty())
          for (const double v :
               this->get_contact().get_row_operator().constraint_values(
                 this->get_solution()))
            max_penetration = std::max(max_penetration, v);
        row.insert(row.end(),
                   {n_active, measure, force, max_pressure, max_penetration});
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(Contact,
                                      "contact",
                                      30,
                                      "active set, contact force and "
                                      "pressure, penetration")
  } // namespace Postprocess
} // namespace dyncontact
