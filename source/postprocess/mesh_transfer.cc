// Adaptive meshes: the energy change of the mesh transfers since the
// previous row, and the largest violation of K_h they left before it was
// projected away; so that Theorem 3.2 can tell what the scheme dissipates
// from what a mesh change does.

#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/mesh_refinement/mesh_transfer.h>
#include <dyncontact/postprocess/interface.h>

#include <algorithm>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class MeshTransfer : public Interface<dim>
    {
    public:
      bool
      applies() const override
      {
        return this->get_mesh_adaptor().is_adaptive();
      }

      std::vector<std::string>
      columns() const override
      {
        std::vector<std::string> names{"energy_transfer",
                                       "transfer_penetration",
                                       "momentum_transfer",
                                       "displacement_transfer"};
        // (the families refused by either limit)
        if (limit_columns() || position_columns())
          names.push_back("coarsening_refused");
        if (limit_columns())
          names.push_back("coarsening_removed");
        if (position_columns())
          names.push_back("coarsening_moved");
        if (tolerance_columns())
          names.insert(names.end(),
                       {"estimated_error", "cells_above_tolerance"});
        return names;
      }

      /// With a coarsening limit: the families it kept and the energy of
      /// what the accepted coarsening removed, over the run; with an Error
      /// tolerance: the largest estimate, and whether cells at Maximum level
      /// stayed above their share.
      std::string
      summary(const Statistics &s, const SummaryInput &input) const override
      {
        if (input.is_static) // (one solve: no adaptation)
          return "";
        const auto        &adaptor   = this->get_mesh_adaptor();
        const double       tolerance = adaptor.get_coarsening_tolerance();
        const double       delta     = adaptor.get_error_tolerance();
        std::ostringstream out;
        out << std::setprecision(6);
        // a column's sum over the run
        const auto total = [&s](const std::string &column) {
          const std::vector<double> &values = s.column(column);
          return std::accumulate(values.begin(), values.end(), 0.);
        };
        if (tolerance > 0. && s.has_column("coarsening_refused"))
          {
            out << "coarsening: " << total("coarsening_refused")
                << " families kept by Mesh "
                << "refinement/"
                << (adaptor.coarsening_limit_of_error_tolerance() ?
                      "Error tolerance (the coarsening limit delta^2/4 = " :
                      "Coarsening tolerance = ")
                << tolerance
                << (adaptor.coarsening_limit_of_error_tolerance() ? ")" : "")
                << (adaptor.get_position_tolerance() > 0. ?
                      " or Position tolerance (their coarsening would have "
                      "removed more than their share of the energy, or "
                      "moved their body by more than the share of the "
                      "motion)" :
                      " (their coarsening would have removed more than "
                      "their share)")
                << "; the parts removed by the others: "
                << total("coarsening_removed") << " J in all\n";
          }
        if (adaptor.get_position_tolerance() > 0. &&
            s.has_column("coarsening_moved"))
          {
            out << "coarsening by the bodies' motion: Mesh "
                   "refinement/Position tolerance = "
                << adaptor.get_position_tolerance()
                << " m; the accepted coarsening's estimated shift of the "
                   "bodies' centres of mass at the end time, as in free "
                   "flight: "
                << total("coarsening_moved") << " m in all";
            if (tolerance == 0.)
              {
                out << "; " << total("coarsening_refused")
                    << " families kept (their coarsening would have shifted "
                       "their body by more than their share)";
              }
            out << "\n";
          }
        if (delta > 0. && s.has_column("estimated_error"))
          {
            double       estimate = 0., above = 0.;
            unsigned int rows_above = 0;
            for (const double e : s.column("estimated_error"))
              estimate = std::max(estimate, e);
            for (const double a : s.column("cells_above_tolerance"))
              {
                above = std::max(above, a);
                rows_above += (a > 0.);
              }
            out << "error tolerance: Mesh refinement/Error tolerance = "
                << delta
                << "; the estimated error (energy norm relative to sqrt(E)) "
                   "at most "
                << estimate << " at an adaptation, before it refined";
            if (rows_above > 0)
              out << "; NOT KEPT"
                  << (adaptor.error_tolerance_split_by_volume() ?
                        " by volume (the error's density, not its sum)" :
                        "")
                  << ": up to " << above
                  << " cells that the tolerance would refine were at Mesh "
                     "refinement/Maximum level = "
                  << adaptor.get_max_level() << " (in " << rows_above
                  << (rows_above == 1 ? " statistics row" : " statistics rows")
                  << "): raise Maximum level or the "
                     "tolerance";
            out << "\n";
          }
        return out.str();
      }

      void
      execute(std::vector<double> &row) override
      {
        const auto &record = this->get_mesh_transfer();
        row.insert(row.end(),
                   {record.energy_change,
                    record.penetration,
                    record.momentum_change,
                    record.displacement_change});
        if (limit_columns() || position_columns())
          row.push_back(record.coarsening_refused);
        if (limit_columns())
          row.push_back(record.coarsening_removed);
        if (position_columns())
          row.push_back(record.coarsening_moved);
        // (0 in rows without an adaptation)
        if (tolerance_columns())
          row.insert(row.end(),
                     {record.estimated_error,
                      double(record.cells_above_tolerance)});
      }

    private:
      /// The columns of the coarsening limit, of the error tolerance: with
      /// each, when the mesh adapts during the run.
      bool
      limit_columns() const
      {
        const auto &adaptor = this->get_mesh_adaptor();
        return adaptor.get_coarsening_tolerance() > 0. &&
               adaptor.adapts_during_run();
      }
      bool
      position_columns() const
      {
        const auto &adaptor = this->get_mesh_adaptor();
        return adaptor.get_position_tolerance() > 0. &&
               adaptor.adapts_during_run();
      }
      bool
      tolerance_columns() const
      {
        const auto &adaptor = this->get_mesh_adaptor();
        return adaptor.get_error_tolerance() > 0. &&
               adaptor.adapts_during_run();
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(MeshTransfer,
                                      "mesh transfer",
                                      "energy change and penetration of mesh "
                                      "transfers")
  } // namespace Postprocess
} // namespace dyncontact
