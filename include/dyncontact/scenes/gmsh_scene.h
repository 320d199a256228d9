#ifndef dyncontact_scenes_gmsh_scene_h
#define dyncontact_scenes_gmsh_scene_h

#include <dyncontact/scenes/interface.h>

#include <set>

namespace dyncontact
{
  /**
   * Any one- or two-body mesh from Gmsh (a .msh file, quadrilaterals or
   * hexahedra). Physical tags are mapped in the prm: cell tags to bodies,
   * boundary tags to clamped (Dirichlet), loaded (Neumann) and contact
   * boundaries. The two bodies must not share vertices. The mesh is checked
   * against the prm: every cell must belong to a body, every tag named in
   * the prm must exist in the mesh, otherwise the run stops with a message.
   */
  template <int dim>
  class GmshScene : public Scene<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    double
    n_coarse_cells() const override
    {
      return n_cells;
    }

    std::string
    input_checksum() const override
    {
      return mesh_checksum;
    }

    void
    create_coarse_mesh(Triangulation<dim, dim> &triangulation) const override;

    unsigned int
    n_bodies() const override
    {
      return body_tags[1].empty() ? 1 : 2;
    }

    std::vector<ContactPair>
    contact_pairs() const override;

    std::vector<DirichletBoundary>
    dirichlet_boundaries() const override;

    std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
    neumann_tractions() const override;

    Tensor<1, dim>
    body_force(const unsigned int body) const override;

    Tensor<1, dim>
    initial_velocity(const Point<dim>  &x,
                     const unsigned int body) const override;

  private:
    std::string                                    mesh_file;
    double                                         n_cells = 0.;
    std::string                                    mesh_checksum;
    std::array<std::set<unsigned int>, 2>          body_tags;
    std::set<unsigned int>                         dirichlet_tags;
    std::set<unsigned int>                         neumann_tags;
    Tensor<1, dim>                                 traction;
    std::array<std::vector<types::boundary_id>, 2> contact_tags;
    std::array<Tensor<1, dim>, 2>                  velocity;
    Tensor<1, dim>                                 gravity;
  };
} // namespace dyncontact

#endif
