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
        return {"energy_transfer", "transfer_penetration"};
      }

      void
      execute(std::vector<double> &row) override
      {
        row.insert(row.end(),
                   {this->get_mesh_transfer().energy_change,
                    this->get_mesh_transfer().penetration});
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(MeshTransfer,
                                      "mesh transfer",
                                      "energy change and penetration of mesh "
                                      "transfers")
  } // namespace Postprocess
} // namespace dyncontact
