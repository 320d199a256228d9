// dyncontact: dynamic contact of viscoelastic bodies with the N-CI, N-CS and
// N-CS++ Newmark schemes. All of the program lives in the library; main only
// hands over the command line.
#include <dyncontact/core/run.h>

int
main(int argc, char **argv)
{
  return dyncontact::main_program(argc, argv);
}
