// Contact pairs by surface (Scene/Gmsh/Contact pairs with the tags of each
// side in parentheses): the stack of three bodies of prm/stack_of_three.prm
// paired surface by surface (the slab's bottom on the floor, the block's
// bottom on the slab's top, the cube on the block's top) moves exactly as
// paired body by body, where every contact tag of a body is in each of its
// pairs and a node keeps the row of the nearer master, with fewer rows (the
// slab's top no longer meets the floor, nor its bottom the block). Bad
// pairs are refused naming the pair: a tag that is not the body's contact
// tag, a contact tag in no pair, a pair of the same surfaces twice, an
// unclosed parenthesis.

#include <cmath>

#include "tests.h"

namespace
{
  /// The number after "contact rows: " in the banner @p text (-1 if none).
  int
  rows_of(const std::string &text)
  {
    const auto at = text.find("contact rows: ");
    return at == std::string::npos ? -1 : std::stoi(text.substr(at + 14));
  }
} // namespace

int
main(int argc, char **argv)
{
  dyncontact::MPIInitFinalize mpi(argc, argv);
  using namespace testing;

  std::ifstream     in(std::string(DYNCONTACT_PRM_DIR) + "/stack_of_three.prm");
  std::stringstream example;
  example << in.rdbuf();
  std::string base = example.str();
  base.replace(base.find("= meshes/"),
               9,
               "= " + std::string(DYNCONTACT_PRM_DIR) + "/meshes/");
  const auto prm = [&](const std::string &name, const std::string &pairs) {
    std::string text = base;
    const auto  at   = text.find("    set Contact pairs");
    text.replace(at,
                 text.find('\n', at) - at,
                 "    set Contact pairs = " + pairs);
    return text + "set Output directory = results-" + name +
           "\nsubsection Time integration\n  set End time = 0.2\nend\n"
           "subsection Output\n  set Write vtu = false\nend\n";
  };

  std::ofstream("bodies.prm")
    << prm("bodies", "1 : obstacle, 2 : 1 : 0.1, 3 : 2 : 0.1");
  std::ofstream("surfaces.prm")
    << prm("surfaces",
           "1 (10) : obstacle, 2 (12) : 1 (11) : 0.1, 3 (14) : 2 (13) : 0.1");
  const Outcome    by_body    = run_program("bodies.prm");
  const Outcome    by_surface = run_program("surfaces.prm");
  const Statistics a = read_statistics("results-bodies/statistics.tsv");
  const Statistics b = read_statistics("results-surfaces/statistics.tsv");
  log() << "the stack paired by body: " << rows_of(by_body.text)
        << " contact rows, by surface: " << rows_of(by_surface.text)
        << " rows: fewer: "
        << check(by_body.status == 0 && by_surface.status == 0 &&
                 rows_of(by_surface.text) > 0 &&
                 rows_of(by_surface.text) < rows_of(by_body.text))
        << "\n";
  // the motion: energies, momenta, mean displacements, contact forces
  double largest = 0.;
  bool   same    = a.rows.size() == b.rows.size() && a.rows.size() > 50;
  for (const std::string &c : a.columns)
    if (same && (c.rfind("energy", 0) == 0 || c.rfind("momentum", 0) == 0 ||
                 c.rfind("mean_displacement", 0) == 0 ||
                 c.find("contact_force") != std::string::npos))
      {
        const auto x = a.column(c), y = b.column(c);
        double     scale = 1e-3, d = 0.;
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            scale = std::max(scale, std::abs(x[i]));
            d     = std::max(d, std::abs(x[i] - y[i]));
          }
        largest = std::max(largest, d / scale);
      }
  log() << "  the same motion (energies, momenta, mean displacements, "
           "contact forces of every pair over "
        << b.rows.size() - 1 << " steps), largest difference < 1e-8: "
        << check(same && largest < 1e-8) << "\n";

  const std::vector<std::pair<std::string, std::pair<std::string, std::string>>>
    cases = {
      {"a tag that is not the body's",
       {"1 (10) : obstacle, 2 (12) : 1 (13), 3 : 2",
        "names tag 13 of body 1, which is not among its Scene/Gmsh/Contact "
        "tags (10, 11)"}},
      {"a contact tag in no pair",
       {"1 (10) : obstacle, 2 (12) : 1, 3 : 2 (12)",
        "a contact boundary (tag 13), but no pair"}},
      {"the same surfaces twice, either way",
       {"1 : obstacle, 2 (12) : 1 (11), 1 (11) : 2 (12), 3 : 2",
        "is listed twice"}},
      {"an unclosed parenthesis",
       {"1 (10 : obstacle, 2 : 1, 3 : 2", "is no pair 'slave : master'"}}};
  for (const auto &[what, input] : cases)
    {
      std::ofstream("bad.prm") << prm("bad", input.first);
      const Outcome outcome = run_program("bad.prm");
      log() << what << " ('" << input.first << "'): refused: "
            << check(outcome.status != 0 && without_backtrace(outcome) &&
                     error_names(outcome, input.second))
            << "\n";
    }
}
