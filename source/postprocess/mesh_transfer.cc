// Adaptive meshes: the energy change of the mesh transfers since the
// previous row, and the largest violation of K_h they left before it was
// projected away; so that Theorem 3.2 can tell what the scheme dissipates
// from what a mesh change does.

#include <dyncontact/mesh_refinement/mesh_adaptor.h>
#include <dyncontact/mesh_refinement/mesh_transfer.h>
#include <dyncontact/postprocess/interface.h>

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
