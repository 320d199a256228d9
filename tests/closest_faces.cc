// The distributed closest-point search (closest_faces) against the whole
// surface: each rank holds a share of a warped master surface (2D: 16
// segments of y = 0.3 x^2; 3D: 8 x 8 bilinear faces of z = 0.4 x y), or of
// a flat one (a rank's bounding box then has no height), dealt
// out like a checkerboard so that every rank's bounding box covers the whole
// surface, or all on rank 0 with the other ranks empty. For points far and
// near, in front of and behind the surface, beside its rim, and exactly over
// shared vertices and edges, ContactMapping::find_closest on the faces
// closest_faces returns must find what it finds on the whole surface: an
// image or none (the rim), the same distance and the same point. Asking only
// the rank of the nearest box, or returning only one face per point, fails
// this (the neighbours across a shared side make the rim).

#include <deal.II/base/mpi.h>

#include <dyncontact/contact/contact_setup.h>

#include <random>

#include "tests.h"

using namespace dealii;
using namespace dyncontact;

template <int dim>
std::vector<MasterFace<dim>>
warped_surface(const bool flat)
{
  std::vector<MasterFace<dim>> faces;
  if (dim == 2)
    for (unsigned int i = 0; i < 16; ++i)
      {
        MasterFace<dim> face;
        for (const unsigned int v : {i, i + 1})
          {
            Point<dim> p;
            p[0] = v / 16.;
            p[1] = flat ? 0. : 0.3 * p[0] * p[0];
            face.vertices.push_back(p);
          }
        face.cell_center = (face.vertices[0] + face.vertices[1]) / 2.;
        face.cell_center[1] -= 0.05;
        faces.push_back(face);
      }
  else
    for (unsigned int j = 0; j < 8; ++j)
      for (unsigned int i = 0; i < 8; ++i)
        {
          MasterFace<dim> face;
          // lexicographic vertex order, as deal.II's faces
          for (const unsigned int b : {0u, 1u})
            for (const unsigned int a : {0u, 1u})
              {
                Point<dim> p;
                p[0] = (i + a) / 8.;
                p[1] = (j + b) / 8.;
                p[2] = flat ? 0. : 0.4 * p[0] * p[1];
                face.vertices.push_back(p);
              }
          Point<dim> centre;
          for (const auto &v : face.vertices)
            centre += v / 4.;
          centre[2] -= 0.05;
          face.cell_center = centre;
          faces.push_back(face);
        }
  return faces;
}

template <int dim>
std::vector<Point<dim>>
probe_points(const unsigned int rank)
{
  std::vector<Point<dim>>                points;
  std::mt19937                           random(17 + rank);
  std::uniform_real_distribution<double> along(-0.5, 1.5), across(-1., 1.);
  for (unsigned int n = 0; n < 100; ++n)
    {
      Point<dim> p;
      for (unsigned int d = 0; d + 1 < dim; ++d)
        p[d] = along(random);
      p[dim - 1] = across(random) * (n % 2 ? 0.05 : 1.);
      points.push_back(p);
    }
  // over shared vertices (and in 3D over shared edges), in front and behind
  for (unsigned int i = 1; i < 8; ++i)
    for (const double offset : {0.3, -0.02})
      {
        Point<dim> p;
        p[0] = i / 8.;
        if (dim == 3)
          p[1] = (i % 2 ? 0.5 : 0.3);
        p[dim - 1] = offset;
        points.push_back(p);
      }
  return points;
}

template <int dim>
void
check(const bool checkerboard, const bool flat)
{
  const MPI_Comm               comm    = MPI_COMM_WORLD;
  const unsigned int           rank    = Utilities::MPI::this_mpi_process(comm);
  const unsigned int           n_ranks = Utilities::MPI::n_mpi_processes(comm);
  const auto                   all     = warped_surface<dim>(flat);
  std::vector<MasterFace<dim>> mine;
  for (unsigned int f = 0; f < all.size(); ++f)
    {
      const unsigned int i = (dim == 2) ? f : f % 8, j = (dim == 2) ? 0 : f / 8;
      const unsigned int owner = checkerboard ? (i + j) % n_ranks : 0;
      if (owner == rank)
        mine.push_back(all[f]);
    }
  const auto                points = probe_points<dim>(rank);
  const auto                near   = closest_faces(mine, points, comm);
  const ContactMapping<dim> whole(all, 0.), distributed(near, 0.);

  unsigned int agree = 0, images = 0;
  for (const auto &x : points)
    {
      const auto a = whole.find_closest(x), b = distributed.find_closest(x);
      if (!a && !b)
        ++agree;
      else if (a && b && std::abs(a->gap - b->gap) <= 1e-12 &&
               a->point.distance(b->point) <= 1e-12)
        {
          ++agree;
          ++images;
        }
    }
  agree  = Utilities::MPI::sum(agree, comm);
  images = Utilities::MPI::sum(images, comm);
  const unsigned int n_points =
    Utilities::MPI::sum<unsigned int>(points.size(), comm);
  testing::log() << dim << "D, " << (flat ? "flat, " : "warped, ")
                 << (checkerboard ? "faces dealt out like a checkerboard" :
                                    "all faces on rank 0")
                 << ": " << n_points << " points, " << images
                 << " with an image; the same image (or none) as on the "
                    "whole surface: "
                 << testing::check(agree == n_points && images > 0 &&
                                   images < n_points)
                 << "\n";
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const bool flat : {false, true})
    for (const bool checkerboard : {true, false})
      {
        check<2>(checkerboard, flat);
        check<3>(checkerboard, flat);
      }
}
