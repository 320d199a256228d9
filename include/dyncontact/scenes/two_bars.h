#ifndef dyncontact_scenes_two_bars_h
#define dyncontact_scenes_two_bars_h

#include <dyncontact/scenes/interface.h>

namespace dyncontact
{
  /**
   * Two identical bars meet head-on: bar 1 = [-g0-L, -g0] x [0,H]^{d-1}
   * moves with +v0 e_x, bar 2 = [g0, g0+L] x [0,H]^{d-1} with -v0 e_x. By
   * symmetry each is the bar impact of ALGORITHMS.md section 7 with the wall
   * at the mid-plane x = 0 (exact for nu = 0): contact from g0/v0 for 2L/c
   * at pressure rho c v0, then each bar leaves with its speed reversed. The
   * numbers of cells across the height may differ between the bars (e.g. 8
   * and 11), which makes the meshes non-matching at the interface.
   */
  template <int dim>
  class TwoBars : public Scene<dim>
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

    unsigned int
    n_bodies() const override
    {
      return 2;
    }

    /// Both bars are of the material of subsection "Material" (lists there
    /// can give each its own; the exact solution then does not apply).
    std::vector<std::string>
    material_subsections() const override
    {
      return {"Material", "Material"};
    }

    std::vector<ContactPair>
    contact_pairs() const override;

    Tensor<1, dim>
    initial_velocity(const Point<dim>  &x,
                     const unsigned int body) const override;

    bool
    has_exact_solution() const override;

    ExactValues<dim>
    exact_solution(const Point<dim> &x, const double t) const override;


  private:
    double                      length;
    double                      height;
    double                      impact_velocity;
    double                      initial_gap;
    std::array<unsigned int, 2> cells_along;
    std::array<unsigned int, 2> cells_across;
  };
} // namespace dyncontact

#endif
