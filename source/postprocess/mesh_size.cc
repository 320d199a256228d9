// The size of the current mesh: active cells and DoFs.

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/postprocess/interface.h>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class MeshSize : public Interface<dim>
    {
    public:
      std::vector<std::string>
      columns() const override
      {
        return {"cells", "dofs"};
      }

      void
      execute(std::vector<double> &row) override
      {
        row.insert(row.end(),
                   {double(this->get_triangulation().n_global_active_cells()),
                    double(this->get_system().get_dof_handler().n_dofs())});
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(MeshSize,
                                      "mesh size",
                                      "active cells and DoFs")
  } // namespace Postprocess
} // namespace dyncontact
