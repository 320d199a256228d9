// The contact pressure of a static run against the scene's exact pressure
// (Hertz): the relative L2 error over the slave surface,
//
//   sqrt( sum_p w_p (p_h,p - p(x_p))^2 / sum_p w_p p(x_p)^2 ),
//
// with the nodal pressure p_h,p = f_p / w_p of an active row (0 of an
// inactive one), w_p the row's boundary weight and x_p the slave node's
// reference position. The sums run over every row, so that pressure outside
// the exact contact zone counts as error as well as pressure missing inside
// it; the weights make the sums quadratures over the contact surface (on a
// plane of symmetry a node's weight is that of its half).
//
// The second column is the largest relative deviation |p_h,p / p(x_p) - 1|
// of a single node where the exact pressure is at least 70% of its largest
// value (r < 0.71 a for Hertz): node-to-node oscillations of the pressure in
// the centre of the contact zone, which the L2 error, dominated by the rim
// where the square root is steep, does not show.

#include <deal.II/base/mpi.h>

#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/row_force.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class PressureError : public Interface<dim>
    {
    public:
      bool
      applies() const override
      {
        return this->get_control().is_static_problem() &&
               this->get_scene().exact_contact_pressure(Point<dim>());
      }

      std::vector<std::string>
      columns() const override
      {
        return {"pressure_error", "pressure_deviation"};
      }

      void
      execute(std::vector<double> &row) override
      {
        const ContactRows  &rows    = this->get_contact().get_rows();
        const StepReport   &report  = this->get_step_report();
        const MPI_Comm      comm    = this->get_mpi_communicator();
        double              sums[2] = {0., 0.};
        std::vector<double> exact(rows.size()), computed(rows.size());
        for (unsigned int p = 0; p < rows.size(); ++p)
          {
            const ContactRow &r = rows.rows[p];
            Point<dim>        x;
            for (unsigned int d = 0; d < dim; ++d)
              x[d] = r.position[d];
            exact[p]    = *this->get_scene().exact_contact_pressure(x);
            computed[p] = row_force(report, p) / r.weight;
            sums[0] +=
              r.weight * (computed[p] - exact[p]) * (computed[p] - exact[p]);
            sums[1] += r.weight * exact[p] * exact[p];
          }
        Utilities::MPI::sum(sums, comm, sums);
        row.push_back(sums[1] > 0. ? std::sqrt(sums[0] / sums[1]) : 0.);

        const double largest =
          Utilities::MPI::max(exact.empty() ?
                                0. :
                                *std::max_element(exact.begin(), exact.end()),
                              comm);
        double deviation = 0.;
        for (unsigned int p = 0; p < rows.size(); ++p)
          if (largest > 0. && exact[p] >= 0.7 * largest)
            deviation =
              std::max(deviation, std::abs(computed[p] / exact[p] - 1.));
        row.push_back(Utilities::MPI::max(deviation, comm));
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(PressureError,
                                      "pressure error",
                                      "relative L2 error of the contact "
                                      "pressure of a static run against the "
                                      "scene's exact one (Hertz)")
  } // namespace Postprocess
} // namespace dyncontact
