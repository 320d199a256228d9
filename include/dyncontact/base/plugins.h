#ifndef dyncontact_base_plugins_h
#define dyncontact_base_plugins_h

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * One registered plugin (a scene, a postprocessor, a refinement
   * criterion): its name (the value users give in the prm), a description
   * for the documentation, the function that declares its parameters, and
   * factories for 2D and 3D. Plugins that run together run in the order the
   * input lists them (all of them: in the order of their names), so that no
   * plugin carries a number chosen against the others.
   */
  template <template <int> class Interface>
  struct PluginInfo
  {
    std::string                                     name;
    std::string                                     description;
    std::function<void(dealii::ParameterHandler &)> declare_parameters;
    std::function<std::unique_ptr<Interface<2>>()>  create_2d;
    std::function<std::unique_ptr<Interface<3>>()>  create_3d;

    template <int dim>
    std::unique_ptr<Interface<dim>>
    create() const
    {
      if constexpr (dim == 2)
        return create_2d();
      else
        return create_3d();
    }
  };

  /**
   * The registry of one kind of plugin, filled from each plugin's own file by
   * a registration macro (as ASPECT's ASPECT_REGISTER_MATERIAL_MODEL), so
   * that the code that uses the plugins names none of them. Plugins are kept
   * sorted by name.
   *
   * The member functions are instantiated once, in the library file of each
   * interface, so that every user sees one list.
   */
  template <template <int> class Interface>
  class PluginRegistry
  {
  public:
    /// Adds a plugin; returns true (for static registration).
    static bool
    add(const PluginInfo<Interface> &info);

    static const std::vector<PluginInfo<Interface>> &
    plugins();

    /// The plugin of this name, or nullptr.
    static const PluginInfo<Interface> *
    find(const std::string &name);

    /// All names, joined by @p separator.
    static std::string
    names(const std::string &separator = "|");

    /// Declares the parameters of every plugin.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

  private:
    static std::vector<PluginInfo<Interface>> &
    list();
  };



  template <template <int> class Interface>
  std::vector<PluginInfo<Interface>> &
  PluginRegistry<Interface>::list()
  {
    static std::vector<PluginInfo<Interface>> plugins;
    return plugins;
  }



  template <template <int> class Interface>
  bool
  PluginRegistry<Interface>::add(const PluginInfo<Interface> &info)
  {
    auto &plugins = list();
    AssertThrow(find(info.name) == nullptr,
                dealii::ExcMessage("Two plugins are registered under the "
                                   "name '" +
                                   info.name + "'."));
    plugins.push_back(info);
    std::stable_sort(plugins.begin(),
                     plugins.end(),
                     [](const auto &a, const auto &b) {
                       return a.name < b.name;
                     });
    return true;
  }



  template <template <int> class Interface>
  const std::vector<PluginInfo<Interface>> &
  PluginRegistry<Interface>::plugins()
  {
    return list();
  }



  template <template <int> class Interface>
  const PluginInfo<Interface> *
  PluginRegistry<Interface>::find(const std::string &name)
  {
    for (const auto &info : list())
      if (info.name == name)
        return &info;
    return nullptr;
  }



  template <template <int> class Interface>
  std::string
  PluginRegistry<Interface>::names(const std::string &separator)
  {
    std::string text;
    for (const auto &info : list())
      text += (text.empty() ? "" : separator) + info.name;
    return text;
  }



  template <template <int> class Interface>
  void
  PluginRegistry<Interface>::declare_parameters(dealii::ParameterHandler &prm)
  {
    for (const auto &info : list())
      if (info.declare_parameters)
        info.declare_parameters(prm);
  }
} // namespace dyncontact

/**
 * Registers the class template @p classname (instantiated for dim = 2, 3)
 * as a plugin of @p interface under @p name. The class needs a default
 * constructor and a static declare_parameters(ParameterHandler &) (the
 * interfaces provide an empty one).
 */
#define DYNCONTACT_REGISTER_PLUGIN(interface, classname, name, description) \
  template class classname<2>;                                              \
  template class classname<3>;                                              \
  namespace                                                                 \
  {                                                                         \
    const bool dyncontact_registered_##classname =                          \
      dyncontact::PluginRegistry<interface>::add(                           \
        {name,                                                              \
         description,                                                       \
         [](dealii::ParameterHandler &prm) {                                \
           classname<2>::declare_parameters(prm);                           \
         },                                                                 \
         []() -> std::unique_ptr<interface<2>> {                            \
           return std::make_unique<classname<2>>();                         \
         },                                                                 \
         []() -> std::unique_ptr<interface<3>> {                            \
           return std::make_unique<classname<3>>();                         \
         }});                                                               \
  }

#endif
