#ifndef dyncontact_scenes_bar_impact_h
#define dyncontact_scenes_bar_impact_h

#include <dyncontact/scenes/interface.h>

namespace dyncontact
{
  /// The exact 1D bar impact solution (ALGORITHMS.md section 7) at axial
  /// position xi in [0, L] of a bar hitting a wall at xi = -g0.
  struct BarSolution1D
  {
    double displacement;
    double velocity;
    double strain;
  };

  BarSolution1D
  exact_bar_impact_1d(const double xi,
                      const double t,
                      const double length,
                      const double wave_speed,
                      const double impact_velocity,
                      const double initial_gap);

  /**
   * ALGORITHMS.md section 7: a bar [0,L] x [0,H]^{d-1} moving with -v0 e_x
   * hits a rigid wall at x = -g0. With nu = 0 the 1D solution is exact in
   * 2D and 3D: contact starts at g0/v0, lasts 2L/c (c = sqrt(E/rho)), the
   * contact pressure is rho c v0, and the bar leaves with +v0. The whole
   * scene can be rotated about the z axis ("Rotation angle"), which turns
   * the wall normal away from the coordinate axes. Optionally the far end
   * x = L is clamped and the bar is loaded by an axial body force or an axial
   * traction on its end x = 0.
   */
  template <int dim>
  class BarImpact : public Scene<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm) override;

    double
    n_coarse_cells() const override;

    void
    create_coarse_mesh(Triangulation<dim, dim> &triangulation) const override;

    std::vector<types::boundary_id>
    contact_boundary_ids() const override
    {
      return {0};
    }

    std::vector<DirichletBoundary>
    dirichlet_boundaries() const override;

    std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
    neumann_tractions() const override;

    Tensor<1, dim>
    body_force(const unsigned int) const override;

    Tensor<1, dim>
    initial_displacement(const Point<dim>  &x,
                         const unsigned int body) const override;

    Tensor<1, dim>
    initial_velocity(const Point<dim>  &x,
                     const unsigned int body) const override;

    /// The wall, met by the bar's end.
    std::vector<RigidObstacle<dim>>
    obstacles() const override;

    bool
    has_exact_solution() const override;

    ExactValues<dim>
    exact_solution(const Point<dim> &x, const double t) const override;


  private:
    /// Rotates a vector from the bar's frame to the global frame.
    Tensor<1, dim>
    rotate(const Tensor<1, dim> &v) const;
    Tensor<1, dim>
    rotate_back(const Tensor<1, dim> &v) const;

    double       length;
    double       height;
    double       impact_velocity;
    double       initial_gap;
    unsigned int cells_along_length;
    double       initial_strain;
    bool         fixed_far_end;
    double       axial_body_force;
    double       end_traction;
    double       angle; // radians
  };
} // namespace dyncontact

#endif
