#ifndef dyncontact_scenes_msh_check_h
#define dyncontact_scenes_msh_check_h

#include <cstddef>
#include <string>

namespace dyncontact
{
  /**
   * Reads the ASCII .msh file @p name (format 2.2 or 4.x) once before
   * deal.II's GridIn does, so that what GridIn cannot read gets a message
   * naming the file and line: a directory, an empty, binary or truncated
   * file, coordinates that are not finite numbers, elements that refer to
   * missing nodes, and elements other than points, lines, quadrilaterals
   * and (in 3D) hexahedra. Returns the number of cells (quadrilaterals in
   * 2D, hexahedra in 3D).
   */
  std::size_t
  check_msh_file(const std::string &name, const int dim);
} // namespace dyncontact

#endif
