#ifndef dyncontact_mesh_refinement_h
#define dyncontact_mesh_refinement_h

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * When and how the mesh adapts during the dynamics (subsection "Mesh
   * refinement"): every "Refinement interval" steps, the cells are marked by
   * the chosen criteria (Kelly indicators of displacement and/or velocity,
   * scaled to the same maximum and added; and the contact zone: cells at
   * slave nodes whose current gap is below the contact-zone distance, and at
   * the master nodes of their images), the top fraction refined and the
   * bottom fraction coarsened within the level bounds, and the state is
   * transferred. Before t = 0 the contact zone is refined "Initial contact
   * refinements" times.
   */
  struct MeshRefinementParameters
  {
    unsigned int interval            = 0;
    unsigned int min_level           = 0;
    unsigned int max_level           = 10;
    double       refine_fraction     = 0.2;
    double       coarsen_fraction    = 0.3;
    bool         kelly_displacement  = false;
    bool         kelly_velocity      = true;
    bool         contact_zone        = true;
    double       contact_distance    = 0.;
    unsigned int initial_refinements = 0;

    bool
    adaptive() const
    {
      return interval > 0 || initial_refinements > 0;
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace dyncontact

#endif
