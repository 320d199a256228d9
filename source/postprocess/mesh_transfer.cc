// Adaptive meshes: the energy change of the mesh transfers since the
// previous row, and the largest violation of K_h they left before it was
// projected away; so that Theorem 3.2 can tell what the scheme dissipates
// from what a mesh change does.

#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/mesh_refinement/mesh_transfer.h>
#include <dyncontact/postprocess/interface.h>

#include <iomanip>
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
        if (this->get_mesh_adaptor().get_coarsening_tolerance() > 0.)
          return {"energy_transfer",
                  "transfer_penetration",
                  "coarsening_refused",
                  "coarsening_removed"};
        return {"energy_transfer", "transfer_penetration"};
      }

      /// With a Coarsening tolerance: the families it kept and the energy
      /// of what the accepted coarsening removed, over the run.
      std::string
      summary(const Statistics &s, const SummaryInput &) const override
      {
        const double tolerance =
          this->get_mesh_adaptor().get_coarsening_tolerance();
        if (tolerance == 0. || !s.has_column("coarsening_refused"))
          return "";
        double refused = 0., removed = 0.;
        for (const double r : s.column("coarsening_refused"))
          refused += r;
        for (const double r : s.column("coarsening_removed"))
          removed += r;
        std::ostringstream out;
        out << std::setprecision(6) << "coarsening: " << refused
            << " families kept by Mesh refinement/Coarsening tolerance = "
            << tolerance
            << " (their coarsening would have removed more than their "
               "share); the parts removed by the others: "
            << removed << " J in all\n";
        return out.str();
      }

      void
      execute(std::vector<double> &row) override
      {
        const auto &record = this->get_mesh_transfer();
        row.insert(row.end(), {record.energy_change, record.penetration});
        if (this->get_mesh_adaptor().get_coarsening_tolerance() > 0.)
          row.insert(row.end(),
                     {double(record.coarsening_refused),
                      record.coarsening_removed});
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(MeshTransfer,
                                      "mesh transfer",
                                      "energy change and penetration of mesh "
                                      "transfers")
  } // namespace Postprocess
} // namespace dyncontact
