// Unit tests of the two-body mapping phi_h (ALGORITHMS.md section 2): closest
// point, normal nu_p (eq. 3) and gap g_p (eq. 2) on flat and curved master
// surfaces in 2D and 3D (a twisted bilinear face against brute-force
// sampling), a slave node exactly on the master surface (g = 0: nu is the
// slave's outward normal), nodes without image (beyond the rim of the master
// surface, beyond the search radius), and the row: master weights N_j at the
// image sum to one, so a rigid translation of both bodies leaves c_p . v = 0.

#include <deal.II/base/mpi.h>

#include <dyncontact/contact/contact_mapping.h>

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace dyncontact;

std::ofstream out("output");

template <int dim>
void
print(const std::string &name, const std::optional<Image<dim>> &image)
{
  out << std::fixed << std::setprecision(5) << name << ": ";
  if (!image)
    {
      out << "no image\n";
      return;
    }
  out << "image " << image->point << ", gap " << image->gap << ", normal "
      << image->normal << "\n";
}

/// A master face with Q1 nodes whose DoFs are numbered from @p first.
template <int dim>
MasterFace<dim>
make_face(const std::vector<Point<dim>> &vertices,
          const Point<dim>              &cell_center,
          const global_dof_index         first)
{
  MasterFace<dim> face;
  face.vertices    = vertices;
  face.cell_center = cell_center;
  face.node_dofs.resize(vertices.size());
  for (unsigned int j = 0; j < vertices.size(); ++j)
    {
      for (unsigned int c = 0; c < dim; ++c)
        face.node_dofs[j][c] = {{first + dim * j + c, 1.}};
      face.node_dof0.push_back(first + dim * j);
    }
  return face;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 2D, flat: the top y = 0 of a block [0,4] x [-1,0], four faces
  {
    std::vector<MasterFace<2>> faces;
    for (unsigned int i = 0; i < 4; ++i)
      faces.push_back(make_face<2>({Point<2>(i, 0.), Point<2>(i + 1, 0.)},
                                   Point<2>(i + 0.5, -0.5),
                                   100 + 4 * i));
    const ContactMapping<2> phi(faces, 1.);
    out << "2D flat master surface y = 0:\n";
    print<2>("  node (1.3, 0.5)", phi.find_image(Point<2>(1.3, 0.5)));
    print<2>("  node (2, 0), on the surface", phi.find_image(Point<2>(2., 0.)));
    print<2>("  node (0, 0.2), above the rim vertex",
             phi.find_image(Point<2>(0., 0.2)));
    print<2>("  node (4.5, 0.2), beyond the rim",
             phi.find_image(Point<2>(4.5, 0.2)));
    print<2>("  node (2, 1.5), beyond the search radius",
             phi.find_image(Point<2>(2., 1.5)));

    // the row: slave node (1.3, 0.5), DoFs 0, 1
    const auto       image = phi.find_image(Point<2>(1.3, 0.5));
    const ContactRow row   = make_two_body_row<2>(
      Point<2>(1.3, 0.5), {{0, 1}}, *image, faces[image->face], 1);
    double sum_N = 0., sum_y = 0.;
    for (const auto &[dof, N] : row.master_nodes)
      sum_N += N;
    for (const auto &[dof, c] : row.entries)
      if (dof % 2 == 1)
        sum_y += c;
    out << "  row: " << row.entries.size() << " entries, gap " << row.gap
        << ", sum of N_j " << sum_N
        << ", c_p . (rigid translation e_y) = " << std::abs(sum_y) << "\n";
  }

  // 2D, curved: a circle of radius 1 around the origin as 16 facets, the
  // master body inside
  {
    const unsigned int         n = 16;
    std::vector<MasterFace<2>> faces;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double a = 2. * M_PI * i / n, b = 2. * M_PI * (i + 1) / n;
        faces.push_back(make_face<2>({Point<2>(std::cos(a), std::sin(a)),
                                      Point<2>(std::cos(b), std::sin(b))},
                                     Point<2>(),
                                     4 * i));
      }
    const ContactMapping<2> phi(faces, 0.5);
    const double            mid = M_PI / n; // bisector of facet 0
    out << "2D curved master surface (16-gon of radius 1):\n";
    const auto image =
      phi.find_image(Point<2>(1.2 * std::cos(mid), 1.2 * std::sin(mid)));
    print<2>("  node at radius 1.2 over a facet's midpoint", image);
    out << "  gap - (1.2 - cos(pi/16)) = "
        << std::abs(image->gap - (1.2 - std::cos(mid))) << "\n";
    print<2>("  node at radius 1.1 over a vertex",
             phi.find_image(Point<2>(1.1, 0.)));
  }

  // 3D, flat: the top z = 0 of a block, 2 x 2 faces over [0,2]^2
  {
    std::vector<MasterFace<3>> faces;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        faces.push_back(make_face<3>({Point<3>(i, j, 0.),
                                      Point<3>(i + 1, j, 0.),
                                      Point<3>(i, j + 1, 0.),
                                      Point<3>(i + 1, j + 1, 0.)},
                                     Point<3>(i + 0.5, j + 0.5, -0.5),
                                     100 * (2 * i + j)));
    const ContactMapping<3> phi(faces, 1.);
    out << "3D flat master surface z = 0:\n";
    print<3>("  node (0.3, 1.7, 0.25)",
             phi.find_image(Point<3>(0.3, 1.7, 0.25)));
    print<3>("  node (1, 1, 0), on the surface",
             phi.find_image(Point<3>(1., 1., 0.)));
    print<3>("  node (2.5, 1, 0.1), beyond the rim",
             phi.find_image(Point<3>(2.5, 1., 0.1)));

    const Point<3>   x(0.3, 1.7, 0.25);
    const auto       image = phi.find_image(x);
    const ContactRow row =
      make_two_body_row<3>(x, {{0, 1, 2}}, *image, faces[image->face], 1);
    double sum_N = 0.;
    for (const auto &[dof, N] : row.master_nodes)
      sum_N += N;
    out << "  row: sum of N_j " << sum_N << "\n";
  }

  // 3D, twisted bilinear face: closest point against brute-force sampling
  {
    const std::vector<Point<3>> v = {Point<3>(0, 0, 0),
                                     Point<3>(1, 0, 0.3),
                                     Point<3>(0, 1, -0.2),
                                     Point<3>(1, 1, 0.4)};
    const MasterFace<3>     face  = make_face<3>(v, Point<3>(0.5, 0.5, -1.), 0);
    const ContactMapping<3> phi({face}, 2.);
    double                  max_difference = 0.;
    for (const Point<3> x : {Point<3>(0.4, 0.6, 0.5),
                             Point<3>(0.8, 0.2, 0.7),
                             Point<3>(0.1, 0.9, 0.3)})
      {
        const auto image = phi.find_image(x);
        double     best  = 1e300;
        for (unsigned int i = 0; i <= 400; ++i)
          for (unsigned int j = 0; j <= 400; ++j)
            {
              const double   s = i / 400., t = j / 400.;
              const Point<3> p(v[0] * ((1 - s) * (1 - t)) +
                               v[1] * (s * (1 - t)) + v[2] * ((1 - s) * t) +
                               v[3] * (s * t));
              best = std::min(best, x.distance(p));
            }
        max_difference = std::max(max_difference, std::abs(image->gap - best));
        // the normal points from x to its image
        max_difference = std::max(max_difference,
                                  (image->normal - (image->point - x) /
                                                     x.distance(image->point))
                                    .norm());
      }
    out << "3D twisted face: closest point matches sampling to 1e-5: "
        << (max_difference < 1e-5 ? "OK" : "FAILED") << "\n";
  }
}
