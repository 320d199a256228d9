#include <deal.II/base/parameter_handler.h>

#include <dyncontact/scene.h>
#include <dyncontact/scenes/bar_impact.h>

namespace dyncontact
{
  void
  declare_scene_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    prm.declare_entry("Name",
                      "bar impact",
                      Patterns::Anything(),
                      "Which scene to run. Available: 'bar impact' (a bar "
                      "against a rigid wall, with an exact solution).");
    prm.leave_subsection();
    BarImpact<2>::declare_parameters(prm);
  }



  template <int dim>
  std::unique_ptr<Scene<dim>>
  create_scene(ParameterHandler &prm, const Material &material)
  {
    prm.enter_subsection("Scene");
    const std::string name = prm.get("Name");
    prm.leave_subsection();

    if (name == "bar impact")
      return std::make_unique<BarImpact<dim>>(prm, material);

    AssertThrow(false,
                ExcMessage("Scene/Name must be one of: 'bar impact'; got '" +
                           name + "'."));
    return nullptr;
  }

  template std::unique_ptr<Scene<2>>
  create_scene<2>(ParameterHandler &, const Material &);
  template std::unique_ptr<Scene<3>>
  create_scene<3>(ParameterHandler &, const Material &);
} // namespace dyncontact
