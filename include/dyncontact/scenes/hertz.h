#ifndef dyncontact_scenes_hertz_h
#define dyncontact_scenes_hertz_h

#include <dyncontact/scenes/interface.h>

namespace dyncontact
{
  /**
   * The classic example of the contact-stabilized Newmark literature: a
   * (viscoelastic) half-cylinder of radius R (2D, scene "hertz") or a ball
   * (3D, scene "ball on block") pressed into, or dropping onto, an elastic
   * block. By symmetry only x >= 0 (and z >= 0 in 3D) is meshed, with
   * rollers on the symmetry planes; the block's bottom is clamped. Body 1 is
   * the cylinder/ball ("Material"), body 2 the block ("Material of body
   * 2"). The load is a uniform traction on the flat top of the cylinder/ball
   * that sums to the load exactly on the mesh (3D: a polygon); in the static
   * scheme it gives Hertz's solution: in 2D (plane strain, load P per unit
   * thickness) the half-width b = sqrt(4PR/(pi E*)) and the peak pressure p0 =
   * 2P/(pi b); in 3D (load P) the radius a = (3PR/(4E*))^{1/3} and p0 = 3P/(2
   * pi a^2); 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
   *
   * With 'Upper block = true' a third body, a block like the lower one
   * (body 3, of "Material of body 2"), lies Initial gap above a whole
   * cylinder or ball; the load acts on its top, the drop velocity moves it
   * with the cylinder or ball, and the static problem has Hertz's solution
   * at both contacts (pair 1 below, pair 2 above).
   *
   * The two registered scenes, "hertz" (2D, subsection Scene/Hertz) and "ball
   * on block" (3D, subsection Scene/Ball on block), are this class with
   * their own subsection.
   */
  template <int dim>
  class HertzScene : public Scene<dim>
  {
  public:
    /// Declares the entries of subsection Scene/@p subsection.
    static void
    declare_parameters(ParameterHandler &prm, const std::string &subsection);

    void
    parse_parameters(ParameterHandler &prm) override;

    double
    n_coarse_cells() const override;

    void
    create_coarse_mesh(Triangulation<dim, dim> &triangulation) const override;

    void
    refine_initial_mesh(Triangulation<dim, dim> &triangulation) const override;

    /// 2, or 3 with the upper block.
    unsigned int
    n_bodies() const override
    {
      return upper_block ? 3 : 2;
    }

    /// "Material" for the cylinder or ball, "Material of body 2" for the
    /// block(s).
    std::vector<std::string>
    material_subsections() const override
    {
      if (upper_block)
        return {"Material", "Material of body 2", "Material of body 2"};
      return {"Material", "Material of body 2"};
    }

    std::vector<ContactPair>
    contact_pairs() const override;

    std::vector<DirichletBoundary>
    dirichlet_boundaries() const override;

    std::vector<types::boundary_id>
    symmetry_boundary_ids() const override;

    std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
    neumann_forces() const override;

    Tensor<1, dim>
    initial_velocity(const Point<dim>  &x,
                     const unsigned int body) const override;

    /// Hertz's contact half-width b (2D) or contact radius a (3D), in m.
    double
    hertz_contact_size() const;

    /// The contact half-width (2D) or radius (3D) at the largest
    /// indentation of the drop, in m, from the energy balance of Hertz's
    /// quasi-static impact: the kinetic energy of the whole half cylinder
    /// or half ball (with the upper block: the whole cylinder or ball and
    /// the upper block) at the Drop velocity and the load's work over the
    /// indentation are stored in Hertz's contact (the load's work over the
    /// initial gap is left out, so that a static run sizes nothing from
    /// it); 0 without a Drop velocity. 3D: the work of
    /// F = 4/3 E* sqrt(R) alpha^(3/2); 2D: of a force P with half-width
    /// b = sqrt(4 P R / (pi E*)) and indentation
    /// alpha = P / (pi E*) (2 ln(4R/b) - 1) (a cylinder on a half-space,
    /// an estimate: the 2D indentation depends on the bodies' size). At
    /// most the radius R.
    double
    impact_contact_size() const;

    /// Hertz's pressure p0 sqrt(1 - r^2/a^2) at the distance r of @p x from
    /// the axis through the first contact point (|x_0| in 2D,
    /// sqrt(x_0^2 + x_2^2) in 3D), with p0 = 2P/(pi b) (2D) or
    /// 3P/(2 pi a^2) (3D); 0 outside the contact zone.
    std::optional<double>
    exact_contact_pressure(const Point<dim> &x) const override;



  protected:
    /// @p subsection: "Hertz" or "Ball on block"; @p scene_dimension: the
    /// only dimension the scene supports.
    HertzScene(const std::string &subsection,
               const unsigned int scene_dimension)
      : subsection(subsection)
      , scene_dimension(scene_dimension)
    {}

  private:
    double
    effective_modulus() const;

    std::string  subsection;
    unsigned int scene_dimension;
    double       radius;
    double       block_width;
    double       block_depth;
    double       load;
    double       drop_velocity;
    double       initial_gap;
    unsigned int contact_refinements;
    unsigned int extra_refinements;
    bool         matched_block_mesh;
    bool         upper_block = false;

    /// Widths of the block's coarse cells along the top, from the plane of
    /// symmetry to the block's width (m).
    std::vector<double>
    block_column_widths() const;
  };

  /// The 2D scene "hertz": a half-cylinder on a block.
  template <int dim>
  class Hertz : public HertzScene<dim>
  {
  public:
    Hertz()
      : HertzScene<dim>("Hertz", 2)
    {}

    static void
    declare_parameters(ParameterHandler &prm)
    {
      HertzScene<dim>::declare_parameters(prm, "Hertz");
    }
  };

  /// The 3D scene "ball on block".
  template <int dim>
  class BallOnBlock : public HertzScene<dim>
  {
  public:
    BallOnBlock()
      : HertzScene<dim>("Ball on block", 3)
    {}

    static void
    declare_parameters(ParameterHandler &prm)
    {
      HertzScene<dim>::declare_parameters(prm, "Ball on block");
    }
  };
} // namespace dyncontact

#endif
