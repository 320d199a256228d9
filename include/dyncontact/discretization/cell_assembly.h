#ifndef dyncontact_discretization_cell_assembly_h
#define dyncontact_discretization_cell_assembly_h

#include <deal.II/base/index_set.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/vector.h>

#include <dyncontact/discretization/semi_discrete_system.h>

#include <utility>
#include <vector>

// What the cell loops of the assembly (assembly.cc, stiffness_assembly.cc)
// share.

namespace dyncontact
{
  namespace CellAssembly
  {
    /// The displacement component and the scalar FE_Q shape function of
    /// each shape function of FE_Q<dim>^dim.
    template <int dim>
    inline std::pair<std::vector<unsigned int>, std::vector<unsigned int>>
    components_and_nodes(const FESystem<dim> &fe)
    {
      std::vector<unsigned int> component(fe.n_dofs_per_cell()),
        node(fe.n_dofs_per_cell());
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          component[i] = fe.system_to_component_index(i).first;
          node[i]      = fe.system_to_component_index(i).second;
        }
      return {component, node};
    }



    /**
     * Adds the values of a cell into an owned Trilinos vector: a locally
     * owned entry directly in the vector's local array (deal.II's add()
     * looks every index up in the vector's map), any other one through
     * add(), which keeps it for compress(). Each entry receives the same
     * additions in the same order as through add() alone. The vector must
     * be freshly reinit()ed (or compressed) on @p owned, without ghosts.
     */
    class OwnedAdder
    {
    public:
      OwnedAdder(VectorType &vector, const IndexSet &owned)
        : vector(vector)
        , owned(owned)
        , data(vector.begin())
        , contiguous(owned.is_contiguous())
        , first(owned.n_elements() > 0 ? owned.nth_index_in_set(0) : 0)
        , n_owned(owned.n_elements())
      {
        Assert(!vector.has_ghost_elements(), ExcGhostsPresent());
        Assert(vector.locally_owned_elements() == owned, ExcInternalError());
      }

      void
      add(const std::vector<types::global_dof_index> &indices,
          const Vector<double>                       &values)
      {
        for (unsigned int i = 0; i < indices.size(); ++i)
          {
            const types::global_dof_index index = indices[i];
            if (contiguous ? (index >= first && index - first < n_owned) :
                             owned.is_element(index))
              data[contiguous ? index - first :
                                owned.index_within_set(index)] += values[i];
            else
              vector.add(1, &index, values.begin() + i);
          }
      }

    private:
      VectorType                   &vector;
      const IndexSet               &owned;
      double                       *data;
      const bool                    contiguous;
      const types::global_dof_index first;
      const types::global_dof_index n_owned;
    };



  } // namespace CellAssembly
} // namespace dyncontact

#endif
