#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/scenes/gmsh_entries.h>
#include <dyncontact/scenes/gmsh_scene.h>

#include <cmath>
#include <map>
#include <memory>
#include <regex>
#include <string>
#include <vector>


// GmshScene's rigid obstacles: Obstacle point and Obstacle normal (one
// half-space), or the list Obstacles (half-spaces, balls, cylinders), each
// met by the pairs that name it.

namespace dyncontact
{
  using namespace GmshEntries;

  namespace
  {
    /// @p v scaled to length 1; refused naming @p entry if it is zero.
    template <int dim>
    Tensor<1, dim>
    unit_vector(Tensor<1, dim> v, const std::string &entry)
    {
      // (scaled first: the square of a tiny component underflows)
      double largest = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        largest = std::max(largest, std::abs(v[d]));
      AssertThrow(largest > 0.,
                  ExcMessage("Scene/Gmsh/" + entry +
                             " must have a length > 0."));
      // (component by component: Tensor's /= multiplies by the reciprocal,
      // which is infinite for a subnormal largest)
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = v[d] / largest;
      const double length = v.norm();
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = v[d] / length;
      return v;
    }



    /// One item of Obstacles: 'plane P normal N', 'sphere C radius R' or
    /// 'cylinder P axis A radius R'.
    template <int dim>
    RigidObstacle<dim>
    parse_obstacle_item(const std::string                   &whole_item,
                        const unsigned int                   k,
                        const std::map<std::string, double> &constants)
    {
      const std::string entry =
        "Obstacles (obstacle " + std::to_string(k) + ", '" + whole_item + "')";
      // a prescribed translation: 'moving d1, d2[, d3]' at the end
      const std::size_t moving = whole_item.find(" moving ");
      const std::string item   = Utilities::trim(whole_item.substr(0, moving));
      std::shared_ptr<Function<dim>> motion;
      if (moving != std::string::npos)
        {
          const auto expressions =
            split_top_level(whole_item.substr(moving + 8), ',');
          AssertThrow(expressions.size() == dim,
                      ExcMessage("Scene/Gmsh/" + entry + ": 'moving' has " +
                                 std::to_string(expressions.size()) +
                                 " components separated by ','; a " +
                                 std::to_string(dim) + "D mesh needs " +
                                 std::to_string(dim) + "."));
          const std::regex place("(^|[^A-Za-z0-9_])[xyz]([^A-Za-z0-9_]|$)");
          for (const std::string &expression : expressions)
            AssertThrow(!std::regex_search(expression, place),
                        ExcMessage("Scene/Gmsh/" + entry + ": the motion '" +
                                   expression +
                                   "' uses x, y or z; an obstacle moves as "
                                   "a whole, with a translation d(t) that "
                                   "depends on t alone."));
          motion =
            make_function<dim>(entry, expressions, constants, /*of_time=*/true);
        }
      const std::string form =
        "Scene/Gmsh/Obstacles: '" + item +
        "' is no 'plane x, y[, z] normal a, b[, c]', 'sphere x, y[, z] "
        "radius r' or 'cylinder x, y, z axis a, b, c radius r'.";
      // the words and the vectors between them
      const std::size_t space = item.find(' ');
      const std::string kind  = item.substr(0, space);
      const std::string rest =
        space == std::string::npos ? "" : item.substr(space);
      RigidObstacle<dim> obstacle;
      const auto between = [&](const std::string &from, const std::string &to) {
        const std::size_t start =
          from.empty() ? 0 : rest.find(" " + from + " ");
        AssertThrow(start != std::string::npos, ExcMessage(form));
        const std::size_t begin = from.empty() ? 0 : start + from.size() + 2;
        const std::size_t end =
          to.empty() ? rest.size() : rest.find(" " + to + " ", begin);
        AssertThrow(end != std::string::npos, ExcMessage(form));
        return Utilities::trim(rest.substr(begin, end - begin));
      };
      const auto radius = [&]() {
        const std::string text  = between("radius", "");
        char             *end   = nullptr;
        const double      value = std::strtod(text.c_str(), &end);
        AssertThrow(!text.empty() && *end == '\0' && std::isfinite(value) &&
                      value > 0. && value <= 1e15,
                    ExcMessage("Scene/Gmsh/" + entry +
                               ": the radius must lie in (0, 1e15] m."));
        return value;
      };
      if (kind == "plane")
        {
          obstacle.shape = RigidObstacle<dim>::Shape::half_space;
          obstacle.point = Point<dim>(
            parse_vector<dim>(between("", "normal"), entry, 1e15, "m"));
          obstacle.normal = unit_vector<dim>(
            parse_vector<dim>(between("normal", ""), entry, 1e15, ""),
            entry + ": its normal");
        }
      else if (kind == "sphere")
        {
          obstacle.shape = RigidObstacle<dim>::Shape::ball;
          obstacle.point = Point<dim>(
            parse_vector<dim>(between("", "radius"), entry, 1e15, "m"));
          obstacle.radius = radius();
        }
      else if (kind == "cylinder")
        {
          AssertThrow(dim == 3,
                      ExcMessage("Scene/Gmsh/" + entry +
                                 ": a cylinder is a 3D obstacle; in 2D, a "
                                 "disc is 'sphere x, y radius r'."));
          obstacle.shape = RigidObstacle<dim>::Shape::cylinder;
          obstacle.point = Point<dim>(
            parse_vector<dim>(between("", "axis"), entry, 1e15, "m"));
          obstacle.normal = unit_vector<dim>(
            parse_vector<dim>(between("axis", "radius"), entry, 1e15, ""),
            entry + ": its axis");
          obstacle.radius = radius();
        }
      else
        AssertThrow(false, ExcMessage(form));
      obstacle.motion = motion;
      if (motion != nullptr)
        obstacle.displacement(0., k); // (refuses a value that is not finite)
      return obstacle;
    }
  } // namespace



  template <int dim>
  void
  GmshScene<dim>::parse_obstacle(ParameterHandler &prm)
  {
    const std::string point  = prm.get("Obstacle point");
    const std::string normal = prm.get("Obstacle normal");
    const std::string list   = prm.get("Obstacles");
    rigid_obstacles.clear();
    if (!list.empty())
      {
        AssertThrow(point.empty() && normal.empty(),
                    ExcMessage("Scene/Gmsh/Obstacles replaces Obstacle point "
                               "and Obstacle normal: leave them out."));
        for (const std::string &item : split_items(list, ';'))
          {
            AssertThrow(!item.empty(),
                        ExcMessage("Scene/Gmsh/Obstacles = '" + list +
                                   "' has an empty item."));
            rigid_obstacles.push_back(parse_obstacle_item<dim>(
              item,
              rigid_obstacles.size() + 1,
              parse_constants(prm.get("Function constants"))));
          }
      }
    else
      {
        AssertThrow(!obstacle_slaves.empty() ||
                      (point.empty() && normal.empty()),
                    ExcMessage("Scene/Gmsh/Obstacle point or Obstacle normal "
                               "is given, but no pair of Scene/Gmsh/Contact "
                               "pairs names the obstacle ('body : "
                               "obstacle'): name it, or leave them out."));
        AssertThrow(obstacle_slaves.empty() ||
                      (!point.empty() && !normal.empty()),
                    ExcMessage("Scene/Gmsh/Contact pairs names the rigid "
                               "obstacle: give both Scene/Gmsh/Obstacle point "
                               "and Scene/Gmsh/Obstacle normal (or "
                               "Scene/Gmsh/Obstacles)."));
        if (!obstacle_slaves.empty())
          {
            RigidObstacle<dim> plane;
            plane.point =
              Point<dim>(parse_vector<dim>(point, "Obstacle point", 1e15, "m"));
            plane.normal = unit_vector<dim>(
              parse_vector<dim>(normal, "Obstacle normal", 1e15, ""),
              "Obstacle normal = '" + normal + "'");
            rigid_obstacles.push_back(plane);
          }
      }
    const unsigned int n = rigid_obstacles.size();
    AssertThrow(!unnumbered_obstacle || n == 1,
                ExcMessage("Scene/Gmsh/Contact pairs names 'obstacle', but "
                           "Scene/Gmsh/Obstacles has " +
                           std::to_string(n) +
                           " obstacles: name each as 'obstacle k'."));
    AssertThrow(obstacle_slaves.size() <= n,
                ExcMessage("Scene/Gmsh/Contact pairs names obstacle " +
                           std::to_string(obstacle_slaves.size()) +
                           ", but Scene/Gmsh/Obstacles has " +
                           std::to_string(n) + "."));
    obstacle_slaves.resize(n);
    obstacle_tags.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        AssertThrow(!obstacle_slaves[k].empty(),
                    ExcMessage("Scene/Gmsh/Obstacles: obstacle " +
                               std::to_string(k + 1) +
                               " is in no pair of Scene/Gmsh/Contact pairs "
                               "('body : obstacle " +
                               std::to_string(k + 1) + "')."));
        rigid_obstacles[k].boundary_ids.assign(obstacle_tags[k].begin(),
                                               obstacle_tags[k].end());
      }
  }



  template <int dim>
  std::vector<RigidObstacle<dim>>
  GmshScene<dim>::obstacles() const
  {
    return rigid_obstacles;
  }



  // (the class is instantiated where it is registered, in gmsh_scene.cc)
  template void
  GmshScene<2>::parse_obstacle(ParameterHandler &);
  template void
  GmshScene<3>::parse_obstacle(ParameterHandler &);
  template std::vector<RigidObstacle<2>>
  GmshScene<2>::obstacles() const;
  template std::vector<RigidObstacle<3>>
  GmshScene<3>::obstacles() const;
} // namespace dyncontact
