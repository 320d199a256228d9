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
   * The top level and subsection Mesh: the dimension, the output
   * directory, the polynomial degree, the global refinements of the
   * scene's mesh and which triangulation holds it; and the folder of the
   * prm file. Every subsection has one owner that declares and reads it
   * (parameter_owners() lists them).
   */
  struct GlobalParameters
  {
    unsigned int dimension           = 2;
    std::string  output_directory    = "results";
    unsigned int initial_refinements = 0;
    /// Mesh/Triangulation = serial: deal.II's Triangulation (one rank)
    /// instead of p4est's.
    bool serial_triangulation = false;
    /// Degree p of FE_Q(p)^dim.
    unsigned int degree = 1;
    /// Folder of the prm file (relative file names in it refer to it).
    std::string input_directory;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace dyncontact

#endif
