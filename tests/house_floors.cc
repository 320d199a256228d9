// The floors of the house (doc/architecture.md): every folder of include/
// and source/ stands on a floor, and a file imports (#include
// <dyncontact/...>) only files of its own folder or of a lower floor. The
// one exception is the top's face: the plugins (refinement criteria,
// writers, statistics) see the simulation through
// core/simulator_access.h, as ASPECT's plugins do. The ground floor, base/,
// imports nothing of the project. A folder that is on no floor fails too:
// a new folder must be given its place here and in doc/architecture.md.
// And the rooms are small: no file of include/ or source/ has more than
// 600 lines, and the simulator (core/simulator.cc), which only wires the
// components and runs the loop, fewer than 400.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

int
main()
{
  // bottom up; folders on one floor do not import each other
  const std::vector<std::vector<std::string>> floors = {{"base"},
                                                        {"scenes"},
                                                        {"discretization"},
                                                        {"contact"},
                                                        {"time_stepping"},
                                                        {"problem"},
                                                        {"mesh_refinement",
                                                         "output"},
                                                        {"postprocess"},
                                                        {"core"},
                                                        {"main.cc"}};
  const std::set<std::string> face       = {"core/simulator_access.h"};
  const unsigned int          face_floor = 6; // from the plugins' floor up

  std::map<std::string, unsigned int> floor_of;
  for (unsigned int f = 0; f < floors.size(); ++f)
    for (const auto &folder : floors[f])
      floor_of[folder] = f;

  std::ofstream out("output");
  for (unsigned int f = floors.size(); f-- > 0;)
    {
      out << "floor " << f + 1 << ":";
      for (const auto &folder : floors[f])
        out << " " << folder;
      out << "\n";
    }

  const std::filesystem::path root(DYNCONTACT_SOURCE_DIR);
  const std::regex include_line("^\\s*#\\s*include\\s*<dyncontact/([^>]+)>");
  unsigned int     n_files = 0, n_imports = 0;
  std::set<std::string> wrong; // sorted: the order of a directory varies
  for (const auto &[top, strip] :
       std::vector<std::pair<std::string, std::string>>{
         {"include/dyncontact", "include/dyncontact/"}, {"source", "source/"}})
    for (const auto &entry :
         std::filesystem::recursive_directory_iterator(root / top))
      {
        if (!entry.is_regular_file())
          continue;
        const std::string name =
          std::filesystem::relative(entry.path(), root / top).string();
        const std::string folder = name.substr(0, name.find('/'));
        ++n_files;
        if (floor_of.count(folder) == 0)
          {
            wrong.insert(top + "/" + name + ": the folder '" + folder +
                         "' is on no floor");
            continue;
          }
        {
          std::ifstream in(entry.path());
          unsigned int  n_lines = 0;
          for (std::string line; std::getline(in, line);)
            ++n_lines;
          const unsigned int largest =
            (top + "/" + name == "source/core/simulator.cc") ? 399 : 600;
          if (n_lines > largest)
            wrong.insert(top + "/" + name + ": " + std::to_string(n_lines) +
                         " lines, more than " + std::to_string(largest));
        }
        std::ifstream in(entry.path());
        unsigned int  line_number = 0;
        for (std::string line; std::getline(in, line);)
          {
            ++line_number;
            std::smatch match;
            if (!std::regex_search(line, match, include_line))
              continue;
            ++n_imports;
            const std::string target = match[1];
            const std::string target_folder =
              target.substr(0, target.find('/'));
            if (target_folder == folder)
              continue;
            const bool known = floor_of.count(target_folder) > 0;
            const bool below =
              known && floor_of[target_folder] < floor_of[folder];
            const bool through_face =
              face.count(target) > 0 && floor_of[folder] >= face_floor;
            if (!below && !through_face)
              {
                wrong.insert(top + "/" + name + ":" +
                             std::to_string(line_number) + ": imports " +
                             target + ", which is " +
                             (known ? "not below it" : "on no floor"));
              }
          }
      }
  for (const auto &w : wrong)
    out << w << "\n";
  out << (n_files > 50 && n_imports > 150 ? "" : "too few files read: ")
      << "imports that run up or sideways, and files too large: "
      << wrong.size() << "\n";
  std::cout << n_files << " files, " << n_imports << " imports read\n";
  return 0;
}
