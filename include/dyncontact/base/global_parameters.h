#ifndef dyncontact_base_global_parameters_h
#define dyncontact_base_global_parameters_h

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace dyncontact
{
  /**
   * The parameters that belong to no single component: the dimension, the
   * output directory, the global refinements of the scene's mesh, and the
   * folder of the prm file. Every other group is declared and read by the
   * component that uses it (declare_all_parameters() collects them).
   */
  struct GlobalParameters
  {
    unsigned int dimension           = 2;
    std::string  output_directory    = "results";
    unsigned int initial_refinements = 0;
    /// Folder of the prm file (relative file names in it refer to it).
    std::string input_directory;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace dyncontact

#endif
