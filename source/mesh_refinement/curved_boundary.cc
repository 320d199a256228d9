// The criterion "curved boundary": the cells on a curved boundary kept at
// Maximum level, so that the bodies' shape and mass are those of the
// finest level.

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/interface.h>
#include <dyncontact/mesh_refinement/mesh_adaptor.h>

namespace dyncontact
{
  namespace MeshRefinement
  {
    /**
     * The cells with a boundary face on a manifold other than the flat one
     * (a circle, a sphere, a cylinder; the scenes' and Gmsh's curved
     * surfaces) are refined up to Maximum level and never coarsened. The
     * cells are (bi/tri)linear in their vertices, so that a coarse cell
     * there cuts a segment off the curve: a ball's mass is 0.8 % below the
     * circle's on the Hertz drop's mesh as the fractions leave it, and
     * its rebound follows. Before t = 0 (after Initial contact
     * refinements) the cells are refined to Maximum level, one level a
     * round, when the mesh adapts during the run or before it.
     */
    template <int dim>
    class CurvedBoundary : public Interface<dim>
    {
    public:
      void
      tag_additional_cells() const override
      {
        const unsigned int max_level = this->get_mesh_adaptor().get_max_level();
        unsigned int       curved    = 0;
        for (const auto &cell :
             this->get_system().get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->manifold_id() != numbers::flat_manifold_id)
                {
                  ++curved;
                  cell->clear_coarsen_flag();
                  if (cell->level() < int(max_level))
                    cell->set_refine_flag();
                  break;
                }
        if (!warned &&
            Utilities::MPI::sum(curved, this->get_mpi_communicator()) == 0)
          {
            warned = true;
            this->get_pcout()
              << "   warning: Mesh refinement/Criteria names curved "
                 "boundary, but no boundary face of the mesh is on a curved "
                 "manifold: it flags no cell."
              << std::endl;
          }
      }

    private:
      mutable bool warned = false;
    };

    DYNCONTACT_REGISTER_REFINEMENT_CRITERION(
      CurvedBoundary,
      "curved boundary",
      "the cells on a curved boundary (a manifold other than flat), always "
      "refined to Maximum level and never coarsened, so that the bodies' "
      "shape and mass are the finest level's")
  } // namespace MeshRefinement
} // namespace dyncontact
