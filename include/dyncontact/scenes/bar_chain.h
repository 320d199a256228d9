#ifndef dyncontact_scenes_bar_chain_h
#define dyncontact_scenes_bar_chain_h

#include <dyncontact/scenes/interface.h>

namespace dyncontact
{
  /**
   * Newton's cradle of bars: a chain of K equal bars [(i-1) L, i L] x
   * [0,H]^{d-1}, i = 1..K, touching end to end and at rest, hit by one more
   * such bar (the striker, [-g0-L, -g0]) moving at v0 e_x. The bodies are
   * the striker (body 1) and the chain (bodies 2..K+1); the pairs are the
   * K touching or facing ends, each end its own boundary id (bar b, counted
   * from 0: left end 2b+1, right end 2b+2).
   *
   * For nu = 0 and an elastic material the exact solution is the 1D one
   * (characteristics): from t0 = g0/v0 a compressive pulse of length 2L,
   * velocity v0/2 and stress -rho c v0/2 runs through the chain; pair i
   * (between bar i-1 and bar i, i = 1..K, bar 0 the striker) is pressed
   * for t in [t0 + (i-1) L/c, t0 + (i+1) L/c], each bar stops at rest when
   * the pulse has passed it, and the last bar leaves at t0 + (K+1) L/c
   * with the impact velocity v0 while all the others are at rest. Up to
   * these times each bar follows the free-free rod of length (K+1) L that
   * the striker and the chain form (no interface carries tension before).
   */
  template <int dim>
  class BarChain : public Scene<dim>
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
      return n_chain + 1;
    }

    /// All bars are of the material of subsection "Material" (lists there
    /// can give each its own; the exact solution then does not apply).
    std::vector<std::string>
    material_subsections() const override
    {
      return std::vector<std::string>(n_bodies(), "Material");
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
    unsigned int n_chain;
    double       length;
    double       height;
    double       impact_velocity;
    double       initial_gap;
    unsigned int cells_along;
    unsigned int cells_across;
  };
} // namespace dyncontact

#endif
