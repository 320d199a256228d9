#ifndef dyncontact_contact_unpaired_bodies_h
#define dyncontact_contact_unpaired_bodies_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <dyncontact/contact/contact_mapping.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/scenes/interface.h>

#include <array>
#include <utility>
#include <vector>

namespace dyncontact
{
  /**
   * The bodies that no contact pair holds apart (e.g. two Gmsh bodies that
   * the input did not pair, or bars of a chain that are no neighbours):
   * nothing keeps them from passing into each other, and this watches that
   * they do not. Each time it is asked, it takes the deformed bounding box
   * of every body (from this rank's locally owned boundary nodes, one sum
   * over the ranks), and only where the boxes of two unpaired bodies meet,
   * looks for the boundary nodes of one that lie inside the other: behind
   * the closest face of the other's deformed boundary (closest_faces(),
   * as ContactSetup::unmatched_penetration() does for the nodes without a
   * row). Bodies far apart cost the boxes only. A scene of one body, or
   * whose bodies are all paired, has nothing to watch.
   */
  template <int dim>
  class UnpairedBodies
  {
  public:
    explicit UnpairedBodies(const MPI_Comm comm);

    /// The pairs of @p n_bodies bodies that no pair of @p pairs joins (a
    /// pair joins the bodies that its two sides' boundary ids lie on), and
    /// this rank's boundary nodes and faces of each body on the current
    /// mesh. Collective.
    void
    setup(const std::vector<ContactPair> &pairs,
          const unsigned int              n_bodies,
          const SemiDiscreteSystem<dim>  &system,
          const Mapping<dim>             &mapping);

    /// A boundary node of @p body inside the body @p other.
    struct Overlap
    {
      double       depth = 0.; ///< in m, behind the closest face; 0: none
      Point<dim>   position;   ///< its position in the reference mesh
      unsigned int body  = 0;
      unsigned int other = 0;
    };

    /// The deepest boundary node of a body inside an unpaired body in the
    /// deformed configuration x + u(x) (its depth 0 if none). Collective.
    Overlap
    deepest(const VectorType &u) const;

    /// Whether any two bodies are unpaired.
    bool
    any() const
    {
      return !body_pairs.empty();
    }

  private:
    struct Node
    {
      Point<dim>                               x;
      std::array<types::global_dof_index, dim> dofs;
    };

    const MPI_Comm                                     comm;
    std::vector<std::pair<unsigned int, unsigned int>> body_pairs;
    /// Per body: this rank's boundary faces, and its locally owned
    /// boundary nodes.
    std::vector<std::vector<MasterFace<dim>>> faces;
    std::vector<std::vector<Node>>            nodes;
    IndexSet                                  locally_owned;
    IndexSet                                  locally_relevant;
  };
} // namespace dyncontact

#endif
