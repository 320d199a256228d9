// Solver effort of the step: active-set iterations of the displacement step
// and of the projection, CG iterations of both, the wall time, the time
// step tau of the step and the adaptive control's error estimate of it.

#include <dyncontact/postprocess/interface.h>
#include <dyncontact/time_stepping/integrators.h>

#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class SolverEffort : public Interface<dim>
    {
    public:
      /// The iterations of the whole run.
      std::string
      summary(const Statistics &s, const SummaryInput &) const override
      {
        std::ostringstream out;
        out << std::setprecision(6) << "iterations: active-set "
            << s.sum("active_set_iterations") << ", projection "
            << s.sum("projection_iterations") << ", CG "
            << s.sum("linear_iterations") << "\n";
        return out.str();
      }


      std::vector<std::string>
      columns() const override
      {
        return {"active_set_iterations",
                "projection_iterations",
                "linear_iterations",
                "step_wall_time",
                "time_step",
                "time_step_estimate"};
      }

      void
      execute(std::vector<double> &row) override
      {
        const StepReport &report = this->get_step_report();
        row.insert(row.end(),
                   {double(report.displacement_solve.iterations),
                    double(report.projection_solve.iterations),
                    double(report.displacement_solve.linear_iterations +
                           report.projection_solve.linear_iterations),
                    this->get_step_wall_time(),
                    report.tau,
                    report.error_estimate});
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(SolverEffort,
                                      "solver effort",
                                      "active-set and CG iterations, wall "
                                      "time, time step and its error estimate")
  } // namespace Postprocess
} // namespace dyncontact
