// The contact of the displacement step: active rows and their measure, the
// contact force 2/tau^2 mu_p (static: mu_p) summed, the largest nodal
// pressure, and the largest violation of the non-penetration condition after
// the step: of C u <= g over the rows, and, for slave nodes without a row,
// the depth of their deformed position behind the deformed master surface
// (ContactSetup::unmatched_penetration), so that a contact the rows miss
// (a search radius too small) cannot report 0. Such a node gets a warning.

#include <dyncontact/contact/contact_setup.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/scenes/interface.h>
#include <dyncontact/time_stepping/row_force.h>
#include <dyncontact/time_stepping/simulation_control.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <string>
#include <tuple>

namespace dyncontact
{
  namespace Postprocess
  {
    namespace
    {
      /// "contact intervals: n: [t0, t1], ... s": an interval runs from the
      /// first to the last step of a run of steps with active rows (in the
      /// column @p column; the first 20 of them are listed).
      std::string
      contact_intervals(const Statistics  &s,
                        const std::string &column = "active_nodes")
      {
        const auto               time   = s.column("time");
        const auto               active = s.column(column);
        const unsigned int       last   = s.rows.size() - 1;
        std::vector<std::string> intervals;
        for (unsigned int r = 0; r <= last; ++r)
          if (active[r] > 0 && (r == 0 || active[r - 1] == 0))
            {
              unsigned int e = r;
              while (e < last && active[e + 1] > 0)
                ++e;
              std::ostringstream interval;
              interval << std::setprecision(6) << "[" << time[r] << ", "
                       << time[e] << "]";
              intervals.push_back(interval.str());
            }
        std::ostringstream out;
        out << "contact intervals: " << intervals.size();
        for (unsigned int i = 0;
             i < std::min<std::size_t>(intervals.size(), 20);
             ++i)
          out << (i == 0 ? ": " : ", ") << intervals[i];
        if (intervals.size() > 20)
          out << ", ...";
        out << (intervals.empty() ? "" : " s") << "\n";
        return out.str();
      }
    } // namespace



    template <int dim>
    class Contact : public Interface<dim>
    {
    public:
      /// (Also in a scene of bodies without a contact pair: the column
      /// max_penetration shows whether they pass into each other.)
      bool
      applies() const override
      {
        return this->get_scene().has_contact() ||
               this->get_scene().n_bodies() > 1;
      }

      /// The contact intervals (dynamic) or the contact zone (static), the
      /// peak contact force and pressure and the largest penetration.
      std::string
      summary(const Statistics &s, const SummaryInput &input) const override
      {
        std::ostringstream out;
        out << std::setprecision(6);
        const std::string  force = input.dim == 2 ? "N/m" : "N";
        const unsigned int last  = s.rows.size() - 1;
        if (input.is_static)
          {
            out << "active nodes: " << s.column("active_nodes")[last]
                << ", measure " << s.column("active_measure")[last] << " "
                << (input.dim == 2 ? "m" : "m^2") << "\n"
                << "contact force: " << s.column("contact_force")[last] << " "
                << force << "\n"
                << "peak contact pressure: "
                << s.column("max_contact_pressure")[last] << " Pa\n"
                << "largest penetration: " << s.column("max_penetration")[last]
                << " m\n";
            return out.str();
          }
        out << contact_intervals(s);
        const auto time = s.column("time");
        for (const auto &[name, what, unit] :
             {std::tuple<std::string, std::string, std::string>{
                "contact_force", "peak contact force", force},
              {"max_contact_pressure", "peak contact pressure", "Pa"},
              {"max_penetration", "largest penetration", "m"}})
          {
            const unsigned int r = s.row_of_largest(name);
            out << what << ": " << s.column(name)[r] << " " << unit
                << " at t = " << time[r] << " s\n";
          }
        return out.str();
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
        double n_active = 0., measure = 0., force = 0., max_pressure = 0.;
        for (unsigned int p = 0; p < rows.size(); ++p)
          if (report.active[p])
            {
              n_active += 1.;
              measure += rows.rows[p].weight;
              const double f_p = row_force(report, p);
              force += f_p;
              max_pressure = std::max(max_pressure, f_p / rows.rows[p].weight);
            }
        double max_penetration = 0.;
        for (const double v :
             this->get_contact().get_row_operator().constraint_values(
               this->get_solution()))
          max_penetration = std::max(max_penetration, v);
        const MPI_Comm comm    = this->get_mpi_communicator();
        double         sums[3] = {n_active, measure, force};
        Utilities::MPI::sum(sums, comm, sums);
        n_active        = sums[0];
        measure         = sums[1];
        force           = sums[2];
        max_pressure    = Utilities::MPI::max(max_pressure, comm);
        max_penetration = Utilities::MPI::max(max_penetration, comm);
        const auto unmatched =
          this->get_contact().unmatched_penetration(this->get_solution());
        if (unmatched.depth > 0.)
          {
            max_penetration = std::max(max_penetration, unmatched.depth);
            const auto        &contact = this->get_contact();
            const unsigned int n_pairs =
              this->get_scene().contact_pairs().size();
            const std::string pair =
              n_pairs + this->get_scene().obstacles().size() > 1 ?
                " of contact pair " + std::to_string(unmatched.pair + 1) :
                std::string();
            std::ostringstream text;
            text << std::setprecision(3) << "the slave node at "
                 << point_text(unmatched.position) << " has no constraint row"
                 << pair << " and lies " << unmatched.depth << " m inside "
                 << (unmatched.pair >= n_pairs ? "a rigid obstacle" :
                                                 "the other body");
            if (unmatched.nearer_master)
              text << ": it kept the row of a master of another pair, "
                      "nearer in the reference configuration, where the "
                      "rows are chosen (the linearised contact assumes "
                      "small displacements).";
            else
              text << ": it was farther than the pair's search radius ("
                   << contact.search_radius(unmatched.pair)
                   << " m, 'Contact/Search radius' or the pair's own) "
                      "from the master surface when the rows were built. "
                      "Increase the search radius.";
            warn(n_warnings, text.str());
          }
        const auto overlap = this->get_contact().get_unpaired_bodies().deepest(
          this->get_solution());
        if (overlap.depth > 0.)
          {
            max_penetration = std::max(max_penetration, overlap.depth);
            std::ostringstream text;
            text << std::setprecision(3) << "bodies " << overlap.body + 1
                 << " and " << overlap.other + 1
                 << ", which no contact pair holds apart, pass into each "
                    "other: the boundary node of body "
                 << overlap.body + 1 << " at " << point_text(overlap.position)
                 << " of the mesh lies " << overlap.depth << " m inside body "
                 << overlap.other + 1
                 << ". Pair them (e.g. in Scene/Gmsh/Contact pairs).";
            warn(n_overlap_warnings, text.str());
          }
        row.insert(row.end(),
                   {n_active, measure, force, max_pressure, max_penetration});
      }

    private:
      unsigned int n_warnings         = 0;
      unsigned int n_overlap_warnings = 0;

      /// "(x, y)" of @p x, as the warnings print it.
      static std::string
      point_text(const Point<dim> &x)
      {
        std::ostringstream out;
        out << std::setprecision(3) << "(";
        for (unsigned int d = 0; d < dim; ++d)
          out << (d > 0 ? ", " : "") << x[d];
        out << ")";
        return out.str();
      }

      /// Prints "warning: step n (t = ...): @p text" for the first three of
      /// a kind (counted in @p count), the third saying that no more follow.
      void
      warn(unsigned int &count, const std::string &text) const
      {
        if (++count > 3)
          return;
        this->get_pcout() << std::setprecision(3) << "   warning: step "
                          << this->get_control().get_step()
                          << " (t = " << this->get_control().get_time()
                          << " s): " << text
                          << (count == 3 ? " (Further such warnings are not "
                                           "printed; see the column "
                                           "max_penetration.)" :
                                           "")
                          << std::endl;
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(Contact,
                                      "contact",
                                      "active set, contact force and "
                                      "pressure, penetration")



    /**
     * The contact of each pair where a scene has more than one (two-body
     * pairs in the order of Scene::contact_pairs(), then the rigid
     * obstacle): its rows, the active ones and their measure, contact force
     * and meas Gamma* (eq. 40) per pair, and each pair's contact intervals in
     * the summary.
     */
    template <int dim>
    class ContactPairs : public Interface<dim>
    {
    public:
      bool
      applies() const override
      {
        return n_pairs() > 1;
      }

      std::string
      summary(const Statistics &s, const SummaryInput &input) const override
      {
        std::ostringstream out;
        out << std::setprecision(6);
        const std::string force = input.dim == 2 ? "N/m" : "N";
        const auto        time  = s.column("time");
        for (unsigned int k = 1; k <= n_pairs(); ++k)
          {
            const std::string pair = "pair" + std::to_string(k);
            out << "pair " << k << obstacle_name(k) << ": ";
            if (input.is_static)
              {
                const unsigned int last = s.rows.size() - 1;
                out << "active nodes: "
                    << s.column("active_nodes_" + pair)[last] << ", measure "
                    << s.column("active_measure_" + pair)[last] << " "
                    << (input.dim == 2 ? "m" : "m^2") << ", contact force "
                    << s.column("contact_force_" + pair)[last] << " " << force
                    << "\n";
                continue;
              }
            const std::string intervals =
              contact_intervals(s, "active_nodes_" + pair);
            const unsigned int r = s.row_of_largest("contact_force_" + pair);
            const auto         f = s.column("contact_force_" + pair);
            if (!(f[r] > 0.))
              {
                out << "no contact\n";
                continue;
              }
            // bodies that touch at rest have active rows with vanishing
            // forces before a pulse arrives: the force shows when it does
            unsigned int first = r, last = r;
            for (unsigned int i = 0; i < f.size(); ++i)
              if (f[i] >= 0.5 * f[r])
                {
                  first = std::min(first, i);
                  last  = i;
                }
            out << intervals.substr(0, intervals.size() - 1)
                << "; peak contact force " << f[r] << " " << force
                << " at t = " << time[r] << " s, at least half of it from "
                << time[first] << " to " << time[last] << " s\n";
          }
        return out.str();
      }


      std::vector<std::string>
      columns() const override
      {
        std::vector<std::string> names;
        for (unsigned int k = 1; k <= n_pairs(); ++k)
          for (const std::string name : {"rows_pair",
                                         "active_nodes_pair",
                                         "active_measure_pair",
                                         "contact_force_pair",
                                         "critical_measure_pair"})
            names.push_back(name + std::to_string(k));
        return names;
      }

      void
      execute(std::vector<double> &row) override
      {
        const ContactRows  &rows   = this->get_contact().get_rows();
        const StepReport   &report = this->get_step_report();
        std::vector<double> sums(5 * n_pairs(), 0.);
        for (unsigned int p = 0; p < rows.size(); ++p)
          {
            double *pair = &sums[5 * rows.rows[p].pair];
            pair[0] += 1.;
            if (report.active[p])
              {
                pair[1] += 1.;
                pair[2] += rows.rows[p].weight;
                pair[3] += row_force(report, p);
              }
            if (p < report.critical.size() && report.critical[p])
              pair[4] += rows.rows[p].weight;
          }
        Utilities::MPI::sum(sums, this->get_mpi_communicator(), sums);
        row.insert(row.end(), sums.begin(), sums.end());
      }

    private:
      /// " (rigid obstacle)" for pair @p k (from 1) if it is one, with
      /// its number among several; "" for a pair of two bodies.
      std::string
      obstacle_name(const unsigned int k) const
      {
        const unsigned int n_two_body =
          this->get_scene().contact_pairs().size();
        if (k <= n_two_body)
          return "";
        return " (rigid obstacle" +
               (n_pairs() - n_two_body > 1 ?
                  " " + std::to_string(k - n_two_body) :
                  std::string()) +
               ")";
      }

      /// The two-body pairs and the obstacles.
      unsigned int
      n_pairs() const
      {
        return this->get_scene().contact_pairs().size() +
               this->get_scene().obstacles().size();
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(ContactPairs,
                                      "contact pairs",
                                      "active rows, contact force and meas "
                                      "Gamma* of each contact pair")
  } // namespace Postprocess
} // namespace dyncontact
