#ifndef dyncontact_scene_h
#define dyncontact_scene_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <dyncontact/material.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
  template <int dim, int spacedim>
  class Triangulation;
} // namespace dealii

namespace dyncontact
{
  using namespace dealii;

  /**
   * A rigid obstacle: the half-space {x : (x - point) . normal <= 0}, with
   * @p normal the unit normal pointing out of the obstacle into free space.
   * For a slave node x_p it gives nu_p = -normal and g_p = (x_p - point) .
   * normal (the paper's eqs. 2-3 with phi(x) the closest obstacle point).
   */
  template <int dim>
  struct RigidObstacle
  {
    Point<dim>     point;
    Tensor<1, dim> normal;
  };

  /// The exact solution at one point and time, where a scene knows it.
  template <int dim>
  struct ExactValues
  {
    Tensor<1, dim> displacement;
    Tensor<1, dim> velocity;
    Tensor<2, dim> displacement_gradient;
  };

  /**
   * A scene decides what exists: the mesh with its boundary ids, the
   * material, loads, initial data, the obstacle and, if known, the exact
   * solution. Nothing is assembled or searched that the scene does not ask
   * for. A new scene is one new file plus one line in scene.cc.
   */
  template <int dim>
  class Scene
  {
  public:
    virtual ~Scene() = default;

    virtual std::string
    name() const = 0;

    /// The coarse mesh with boundary ids (before global refinement).
    virtual void
    create_coarse_mesh(Triangulation<dim, dim> &triangulation) const = 0;

    virtual const Material &
    material() const = 0;

    /// Boundary ids of the possible contact boundary Gamma_C of the slave.
    virtual std::vector<types::boundary_id>
    contact_boundary_ids() const = 0;

    /// Boundary ids with homogeneous Dirichlet data (all components).
    virtual std::vector<types::boundary_id>
    dirichlet_boundary_ids() const
    {
      return {};
    }

    /// Constant Neumann tractions (Pa) per boundary id.
    virtual std::vector<std::pair<types::boundary_id, Tensor<1, dim>>>
    neumann_tractions() const
    {
      return {};
    }

    /// Constant body force density (N/m^3).
    virtual Tensor<1, dim>
    body_force() const
    {
      return Tensor<1, dim>();
    }

    virtual Tensor<1, dim>
    initial_displacement(const Point<dim> &) const
    {
      return Tensor<1, dim>();
    }

    virtual Tensor<1, dim>
    initial_velocity(const Point<dim> &x) const = 0;

    /// The rigid obstacle, if the scene has one.
    virtual std::optional<RigidObstacle<dim>>
    obstacle() const
    {
      return {};
    }

    virtual bool
    has_exact_solution() const
    {
      return false;
    }

    virtual ExactValues<dim>
    exact_solution(const Point<dim> &, const double) const
    {
      return {};
    }

    /// The exact contact pressure (Pa) while in contact, 0 if unknown.
    virtual double
    reference_contact_pressure() const
    {
      return 0.;
    }
  };

  /// Declares subsection "Scene" with the entries of every scene.
  void
  declare_scene_parameters(ParameterHandler &prm);

  /// Creates the scene named in "Scene/Name" with the given material.
  template <int dim>
  std::unique_ptr<Scene<dim>>
  create_scene(ParameterHandler &prm, const Material &material);
} // namespace dyncontact

#endif
