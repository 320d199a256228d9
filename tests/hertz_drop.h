// The viscous Hertz drop that tests/step_matrix_free and
// tests/step_multigrid run with each step operator and preconditioner.
#ifndef dyncontact_tests_hertz_drop_h
#define dyncontact_tests_hertz_drop_h

#include "tests.h"

namespace testing
{
  /// The 2D Hertz drop (two bodies, the cylinder viscous, the contact
  /// zone refined twice: hanging nodes) with FE_Q(@p degree) and the
  /// @p mass matrix ("lumped" or "consistent"), N-CS++, 25 steps.
  inline std::string
  hertz_prm(const unsigned int degree, const std::string &mass)
  {
    return "set Dimension = 2\n"
           "set Polynomial degree = " +
           std::to_string(degree) +
           "\n"
           "set Output directory = output-hertz\n" +
           scene_prm("hertz",
                     "    set Radius = 1\n    set Load = 0.005\n"
                     "    set Drop velocity = 0.1\n"
                     "    set Initial gap = 0.01\n"
                     "    set Contact zone refinements = 2\n") +
           "subsection Mesh\n  set Initial global refinements = 1\nend\n"
           "subsection Material\n  set Young's modulus = 1\n"
           "  set Poisson's ratio = 0.3\n  set Density = 1\n"
           "  set Viscous shear modulus = 0.01\n"
           "  set Viscous Lame parameter = 0.01\nend\n"
           "subsection Time integration\n  set Scheme = N-CS++\n"
           "  set Time step = 0.01\n  set End time = 0.25\n"
           "  set Mass matrix = " +
           mass +
           "\nend\n"
           "subsection Output\n  set Write vtu = false\nend\n";
  }
} // namespace testing

#endif
