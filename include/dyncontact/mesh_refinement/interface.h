#ifndef dyncontact_mesh_refinement_interface_h
#define dyncontact_mesh_refinement_interface_h

#include <deal.II/lac/vector.h>

#include <dyncontact/base/plugins.h>
#include <dyncontact/core/simulator_access.h>

#include <cmath>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  namespace MeshRefinement
  {
    /**
     * A refinement criterion (as ASPECT's mesh refinement plugins): it adds
     * indicators per active cell, from which the top and bottom fractions
     * of the cells are refined and coarsened, and/or it flags cells that
     * must be refined whatever the indicators say. A new criterion is one
     * file with its class and the line
     * DYNCONTACT_REGISTER_REFINEMENT_CRITERION(Class, "name", position,
     * "what"); the name is what "Mesh refinement/Criteria" lists.
     */
    template <int dim>
    class Interface : public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      virtual void
      parse_parameters(ParameterHandler &)
      {}

      /// Adds this criterion's indicators, scaled to maximum 1 over all
      /// ranks, to @p indicators (one per active cell); none by default.
      virtual void
      execute(Vector<float> &indicators) const
      {
        (void)indicators;
      }

      /// Sets the refine flag of cells that must be refined (and clears
      /// their coarsen flag); none by default.
      virtual void
      tag_additional_cells() const
      {}
    };

    /// Adds @p eta (one value per active cell), scaled to maximum 1 over
    /// all ranks of @p comm, to @p indicators; nothing if @p eta is zero
    /// everywhere.
    void
    add_scaled(const Vector<float> &eta,
               Vector<float>       &indicators,
               const MPI_Comm       comm);


    /// The energy of the error on each of this rank's cells K (J, J/m in
    /// 2D), 1/2 rho h_K^2 k_K(u_dot)^2 + 1/2 (lambda + 2 mu) k_K(u)^2, with
    /// k_K Zienkiewicz and Zhu's indicator ||G x - grad x||_L2(K) (an
    /// estimate of the gradient's error on K; the velocity's L2 error is
    /// about h_K times it), unscaled.
    template <int dim>
    void
    energy_error_indicators(const SimulatorAccess<dim> &access,
                            Vector<float>              &eta);


    /**
     * A criterion whose indicators @p estimate computes from the
     * displacement, or from the velocity if @p of_velocity (estimate sets
     * the entries of this rank's cells), added scaled by add_scaled(): the
     * Kelly and the recovery criteria.
     */
    template <int dim,
              void (*estimate)(const SimulatorAccess<dim> &,
                               const VectorType &,
                               Vector<float> &),
              bool of_velocity>
    class FieldCriterion : public Interface<dim>
    {
    public:
      void
      execute(Vector<float> &indicators) const override
      {
        Vector<float> eta(indicators.size());
        estimate(*this,
                 of_velocity ? this->get_velocity() : this->get_solution(),
                 eta);
        add_scaled(eta, indicators, this->get_mpi_communicator());
      }
    };

    /// Whether a slave node of current gap @p gap (m) is in the contact
    /// zone: the gap is at most Contact zone/Distance @p distance (up to a
    /// round-off of 1e-10 of it, so that a gap equal to the distance is in)
    /// or below two cell sizes at the node, the size from the @p weight of
    /// its contact row (its share of the slave surface, m^(dim-1)).
    template <int dim>
    inline bool
    in_contact_zone(const double gap,
                    const double distance,
                    const double weight)
    {
      return gap <= (1. + 1e-10) * distance ||
             gap < 2. * std::pow(weight, 1. / (dim - 1));
    }
  } // namespace MeshRefinement

  extern template class PluginRegistry<MeshRefinement::Interface>;
} // namespace dyncontact

/// Registers a refinement criterion (the criteria of Mesh
/// refinement/Criteria run in the order listed there).
#define DYNCONTACT_REGISTER_REFINEMENT_CRITERION(classname, name, description) \
  DYNCONTACT_REGISTER_PLUGIN(dyncontact::MeshRefinement::Interface,            \
                             classname,                                        \
                             name,                                             \
                             description)

#endif
