#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dyncontact/scenes/gmsh_entries.h>
#include <dyncontact/scenes/gmsh_scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>


// GmshScene's Contact pairs: slave : master, by body or by surface.

namespace dyncontact
{
  using namespace GmshEntries;



  namespace
  {
    /// The items of @p list separated by ',' outside parentheses.
    std::vector<std::string>
    split_pair_list(const std::string &list)
    {
      std::vector<std::string> items(1);
      int                      depth = 0;
      for (const char c : list)
        {
          depth += (c == '(') - (c == ')');
          if (c == ',' && depth == 0)
            items.emplace_back();
          else
            items.back() += c;
        }
      for (auto &item : items)
        item = Utilities::trim(item);
      if (items.size() == 1 && items[0].empty())
        return {};
      return items;
    }
  } // namespace



  template <int dim>
  void
  GmshScene<dim>::parse_contact_pairs(ParameterHandler &prm)
  {
    const unsigned int n    = body_tags.size();
    const std::string  list = prm.get("Contact pairs");
    const std::string  form =
      "' is no pair 'slave : master' of body numbers (the master can be "
      "'obstacle', or 'obstacle k' for the k-th of Obstacles), or 'slave : "
      "master : search radius'; a body may name "
      "the contact tags the pair uses in parentheses, e.g. '2 (12) : 1 "
      "(11, 13)'.";
    for (const std::string &item : split_pair_list(list))
      {
        const auto sides = split_items(item, ':');
        AssertThrow(sides.size() < 2 || sides[0].rfind("obstacle", 0) != 0,
                    ExcMessage("Scene/Gmsh/Contact pairs: the pair '" + item +
                               "' makes the rigid obstacle the slave; it "
                               "can only be the master (write 'body : "
                               "obstacle')."));
        AssertThrow(sides.size() == 2 || sides.size() == 3,
                    ExcMessage("Scene/Gmsh/Contact pairs: '" + item + form));
        // 'obstacle' or 'obstacle k': the index of the obstacle
        const bool   with_obstacle = sides[1].rfind("obstacle", 0) == 0;
        unsigned int obstacle      = 0;
        if (with_obstacle)
          {
            const std::string number = Utilities::trim(sides[1].substr(8));
            char             *end    = nullptr;
            const long        k      = std::strtol(number.c_str(), &end, 10);
            AssertThrow(number.empty() || (*end == '\0' && k >= 1 && k <= 1000),
                        ExcMessage("Scene/Gmsh/Contact pairs: '" + item +
                                   form));
            if (number.empty())
              unnumbered_obstacle = true;
            else
              obstacle = k - 1;
            if (obstacle_slaves.size() <= obstacle)
              {
                obstacle_slaves.resize(obstacle + 1);
                obstacle_tags.resize(obstacle + 1);
              }
          }
        // each side: a body number, and the tags in parentheses, if any
        std::array<long, 2>                   body{{0, 0}};
        std::array<std::set<unsigned int>, 2> named;
        for (unsigned int k = 0; k < (with_obstacle ? 1 : 2); ++k)
          {
            std::string       side  = sides[k];
            const std::size_t open  = side.find('(');
            bool              valid = true;
            if (open != std::string::npos)
              {
                valid = side.back() == ')';
                if (valid)
                  {
                    std::string inside =
                      side.substr(open + 1, side.size() - open - 2);
                    std::replace(inside.begin(), inside.end(), ' ', ',');
                    std::string tags;
                    for (const auto &t : Utilities::split_string_list(inside))
                      if (!t.empty())
                        tags += (tags.empty() ? "" : ",") + t;
                    named[k] =
                      parse_tags(tags, "Contact pairs ('" + item + "')");
                    valid = !named[k].empty();
                  }
                side = Utilities::trim(side.substr(0, open));
              }
            char *end = nullptr;
            body[k]   = std::strtol(side.c_str(), &end, 10);
            AssertThrow(valid && !side.empty() && *end == '\0',
                        ExcMessage("Scene/Gmsh/Contact pairs: '" + item +
                                   form));
          }
        double radius = 0.;
        if (sides.size() == 3)
          {
            char *end = nullptr;
            radius    = std::strtod(sides[2].c_str(), &end);
            AssertThrow(!sides[2].empty() && *end == '\0',
                        ExcMessage("Scene/Gmsh/Contact pairs: '" + item +
                                   form));
          }
        for (unsigned int k = 0; k < (with_obstacle ? 1 : 2); ++k)
          AssertThrow(body[k] >= 1 && body[k] <= long(n),
                      ExcMessage("Scene/Gmsh/Contact pairs: the pair '" + item +
                                 "' names body " + std::to_string(body[k]) +
                                 ", but Scene/Gmsh/Bodies has bodies 1 "
                                 "to " +
                                 std::to_string(n) + "."));
        AssertThrow(body[0] != body[1],
                    ExcMessage("Scene/Gmsh/Contact pairs: the pair '" + item +
                               "' pairs body " + std::to_string(body[0]) +
                               " with itself."));
        AssertThrow(sides.size() == 2 || !with_obstacle,
                    ExcMessage("Scene/Gmsh/Contact pairs: the pair '" + item +
                               "' gives the rigid obstacle a search "
                               "radius; every slave node of the obstacle "
                               "gets a row, leave the radius out."));
        AssertThrow(sides.size() == 2 ||
                      (std::isfinite(radius) && radius > 0. && radius <= 1e15),
                    ExcMessage("Scene/Gmsh/Contact pairs: the search "
                               "radius of the pair '" +
                               item + "' must lie in (0, 1e15] m."));
        // the tags of each side: those named, which must be the body's
        // contact tags, or all of them
        std::array<std::vector<types::boundary_id>, 2> tags;
        for (unsigned int k = 0; k < (with_obstacle ? 1 : 2); ++k)
          {
            const auto &own = contact_tags[body[k] - 1];
            AssertThrow(!own.empty(),
                        ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                   item + "' names body " +
                                   std::to_string(body[k]) +
                                   ", which has no Scene/Gmsh/Contact "
                                   "tags."));
            for (const unsigned int tag : named[k])
              {
                std::string list_of_own;
                for (const auto t : own)
                  list_of_own +=
                    (list_of_own.empty() ? "" : ", ") + std::to_string(t);
                AssertThrow(std::find(own.begin(), own.end(), tag) != own.end(),
                            ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                       item + "' names tag " +
                                       std::to_string(tag) + " of body " +
                                       std::to_string(body[k]) +
                                       ", which is not among its "
                                       "Scene/Gmsh/Contact tags (" +
                                       list_of_own + ")."));
              }
            tags[k] = named[k].empty() ?
                        own :
                        std::vector<types::boundary_id>(named[k].begin(),
                                                        named[k].end());
          }
        const unsigned int slave  = body[0] - 1;
        const unsigned int master = with_obstacle ? 0 : body[1] - 1;
        if (with_obstacle)
          {
            bool added = false;
            for (const auto tag : tags[0])
              added = obstacle_tags[obstacle].insert(tag).second || added;
            AssertThrow(added,
                        ExcMessage("Scene/Gmsh/Contact pairs: the pair '" +
                                   item +
                                   "' is listed twice (its tags already meet "
                                   "the obstacle)."));
            obstacle_slaves[obstacle].insert(slave);
          }
        else
          {
            const auto sorted = [](std::vector<types::boundary_id> v) {
              std::sort(v.begin(), v.end());
              return v;
            };
            for (const BodyPair &pair : pairs)
              AssertThrow(!((pair.slave == slave && pair.master == master &&
                             sorted(pair.slave_tags) == sorted(tags[0]) &&
                             sorted(pair.master_tags) == sorted(tags[1])) ||
                            (pair.slave == master && pair.master == slave &&
                             sorted(pair.slave_tags) == sorted(tags[1]) &&
                             sorted(pair.master_tags) == sorted(tags[0]))),
                          ExcMessage(
                            "Scene/Gmsh/Contact pairs: the pair '" + item +
                            "' is listed twice (a pair of two surfaces is "
                            "listed once, either way)."));
            pairs.push_back({slave, master, radius, tags[0], tags[1]});
          }
      }
  }



  // (the class is instantiated where it is registered, in gmsh_scene.cc)
  template void
  GmshScene<2>::parse_contact_pairs(ParameterHandler &);
  template void
  GmshScene<3>::parse_contact_pairs(ParameterHandler &);
} // namespace dyncontact
