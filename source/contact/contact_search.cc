// The parallel contact search: which master faces a rank needs for its
// slave nodes, found by exchanging one bounding box per rank and then only
// the faces near (faces_near()) or closest to (closest_faces()) the nodes.

#include <deal.II/base/utilities.h>
#include <deal.II/numerics/rtree.h>

#include <boost/serialization/array.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <dyncontact/contact/contact_search.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <utility>

namespace dyncontact
{
  namespace
  {
    /// MINMAXDIST (Roussopoulos et al. 1995): every face of the bounding
    /// box of a set of faces' vertices touches a vertex, so some face lies
    /// at most this far from @p x.
    template <int dim>
    double
    min_max_distance(const BoundingBox<dim> &box, const Point<dim> &x)
    {
      const auto [lower, upper] = box.get_boundary_points();
      double far_squared        = 0.; // to the farther side, every axis
      for (unsigned int d = 0; d < dim; ++d)
        far_squared += std::pow(std::max(std::abs(x[d] - lower[d]),
                                         std::abs(x[d] - upper[d])),
                                2);
      double best = std::numeric_limits<double>::infinity();
      for (unsigned int k = 0; k < dim; ++k)
        {
          const double far =
            std::max(std::abs(x[k] - lower[k]), std::abs(x[k] - upper[k]));
          const double near =
            std::min(std::abs(x[k] - lower[k]), std::abs(x[k] - upper[k]));
          best = std::min(best, far_squared - far * far + near * near);
        }
      return std::sqrt(std::max(best, 0.));
    }



    /// Every rank's bounding box of its @p faces, with the rank (ranks
    /// without faces left out). Collective.
    template <int dim>
    std::vector<std::pair<BoundingBox<dim>, unsigned int>>
    rank_boxes(const std::vector<MasterFace<dim>> &faces, const MPI_Comm comm)
    {
      std::vector<double> box(2 * dim, 0.);
      if (!faces.empty())
        {
          BoundingBox<dim> local(faces[0].vertices);
          for (const auto &face : faces)
            local.merge_with(BoundingBox<dim>(face.vertices));
          for (unsigned int d = 0; d < dim; ++d)
            {
              box[d]       = local.get_boundary_points().first[d];
              box[dim + d] = local.get_boundary_points().second[d];
            }
        }
      else
        for (unsigned int d = 0; d < dim; ++d)
          {
            box[d]       = 1.;
            box[dim + d] = -1.; // empty
          }
      const auto boxes = Utilities::MPI::all_gather(comm, box);
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> result;
      for (unsigned int rank = 0; rank < boxes.size(); ++rank)
        if (boxes[rank][0] <= boxes[rank][dim])
          {
            Point<dim> lower, upper;
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = boxes[rank][d];
                upper[d] = boxes[rank][dim + d];
              }
            result.emplace_back(std::make_pair(lower, upper), rank);
          }
      return result;
    }



    /// Sends every rank of @p wanted the @p faces it marks (in this rank's
    /// order) and returns what this rank receives, in rank order.
    /// Collective.
    template <int dim>
    std::vector<MasterFace<dim>>
    exchange_faces(const std::vector<MasterFace<dim>>              &faces,
                   const std::map<unsigned int, std::vector<bool>> &wanted,
                   const MPI_Comm                                   comm)
    {
      std::map<unsigned int, std::vector<MasterFace<dim>>> answers;
      for (const auto &[rank, marked] : wanted)
        {
          auto &answer = answers[rank];
          for (unsigned int f = 0; f < faces.size(); ++f)
            if (marked[f])
              answer.push_back(faces[f]);
        }
      std::vector<MasterFace<dim>> received;
      for (const auto &[rank, rank_faces] :
           Utilities::MPI::some_to_some(comm, answers))
        received.insert(received.end(), rank_faces.begin(), rank_faces.end());
      return received;
    }



    /// Step 1 of closest_faces(): each of the @p points goes to the ranks
    /// whose faces' box is not farther than the least MINMAXDIST of the
    /// boxes (some face lies that near). Fills @p requests with the
    /// coordinates for each rank and @p asked with the numbers of the
    /// points sent to it. Collective.
    template <int dim>
    void
    request_nearest_ranks(
      const std::vector<MasterFace<dim>>                &faces,
      const std::vector<Point<dim>>                     &points,
      const MPI_Comm                                     comm,
      std::map<unsigned int, std::vector<double>>       &requests,
      std::map<unsigned int, std::vector<unsigned int>> &asked)
    {
      const auto rank_tree = pack_rtree(rank_boxes(faces, comm));
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          const Point<dim>                                      &x = points[i];
          std::vector<std::pair<BoundingBox<dim>, unsigned int>> nearest;
          rank_tree.query(boost::geometry::index::nearest(x, 1),
                          std::back_inserter(nearest));
          if (nearest.empty())
            break; // no rank has faces
          // MINMAXDIST with a margin for round-off (relative to the distance
          // and to the box: a point on a degenerate box, a flat surface)
          auto bound_of = [&x](const BoundingBox<dim> &box) {
            const auto [lower, upper] = box.get_boundary_points();
            return min_max_distance(box, x) * (1. + 1e-12) +
                   1e-12 * lower.distance(upper);
          };
          double bound = bound_of(nearest[0].first);
          std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
          rank_tree.query(boost::geometry::index::intersects(
                            search_box(x, bound)),
                          std::back_inserter(hits));
          for (const auto &hit : hits)
            bound = std::min(bound, bound_of(hit.first));
          for (const auto &hit : hits)
            if (box_distance(hit.first, x) <= bound)
              {
                requests[hit.second].insert(requests[hit.second].end(),
                                            x.begin_raw(),
                                            x.end_raw());
                asked[hit.second].push_back(i);
              }
        }
    }



    /// The ContactMapping of this rank's @p faces, built in @p local on
    /// first use (only on a rank that is asked).
    template <int dim>
    ContactMapping<dim> *
    local_mapping(std::unique_ptr<ContactMapping<dim>> &local,
                  const std::vector<MasterFace<dim>>   &faces)
    {
      if (!local)
        local = std::make_unique<ContactMapping<dim>>(faces, 0.);
      return local.get();
    }



    /// Step 2 of closest_faces(): each rank answers the @p requests with
    /// the distance to its closest face, and keeps the points it received
    /// in @p received_points for step 3. Returns the least distance of each
    /// of the @p points (those @p asked of the ranks). Collective.
    template <int dim>
    std::vector<double>
    least_distances(
      const std::vector<MasterFace<dim>>                &faces,
      const std::vector<Point<dim>>                     &points,
      const std::map<unsigned int, std::vector<double>> &requests,
      std::map<unsigned int, std::vector<unsigned int>> &asked,
      const MPI_Comm                                     comm,
      std::unique_ptr<ContactMapping<dim>>              &local,
      std::map<unsigned int, std::vector<Point<dim>>>   &received_points)
    {
      std::map<unsigned int, std::vector<double>> distances;
      for (const auto &[rank, coordinates] :
           Utilities::MPI::some_to_some(comm, requests))
        for (std::size_t i = 0; i + dim <= coordinates.size(); i += dim)
          {
            Point<dim> x;
            for (unsigned int d = 0; d < dim; ++d)
              x[d] = coordinates[i + d];
            received_points[rank].push_back(x);
            distances[rank].push_back(local_mapping(local, faces)->distance(x));
          }
      std::vector<double> least(points.size(),
                                std::numeric_limits<double>::infinity());
      for (const auto &[rank, answer] :
           Utilities::MPI::some_to_some(comm, distances))
        for (unsigned int k = 0; k < answer.size(); ++k)
          least[asked[rank][k]] = std::min(least[asked[rank][k]], answer[k]);
      return least;
    }
  } // namespace



  template <int dim>
  std::vector<MasterFace<dim>>
  closest_faces(const std::vector<MasterFace<dim>> &faces,
                const std::vector<Point<dim>>      &points,
                const MPI_Comm                      comm)
  {
    // 1. each point goes to the ranks whose faces' box is not farther than
    // the least MINMAXDIST of the boxes (some face lies that near)
    std::map<unsigned int, std::vector<double>>       requests;
    std::map<unsigned int, std::vector<unsigned int>> asked; // point numbers
    request_nearest_ranks(faces, points, comm, requests, asked);

    // 2. each rank answers with the distance to its closest face, and keeps
    // the points for step 3
    // (built only on a rank that is asked)
    std::unique_ptr<ContactMapping<dim>>            local;
    std::map<unsigned int, std::vector<Point<dim>>> received_points;
    const std::vector<double>                       least = least_distances(
      faces, points, requests, asked, comm, local, received_points);

    // 3. the same ranks get the least distance of each point and answer
    // with their faces that near
    std::map<unsigned int, std::vector<double>> least_sent;
    for (const auto &[rank, numbers] : asked)
      for (const unsigned int i : numbers)
        least_sent[rank].push_back(least[i]);
    std::map<unsigned int, std::vector<bool>> wanted;
    for (const auto &[rank, bounds] :
         Utilities::MPI::some_to_some(comm, least_sent))
      {
        auto &marked = wanted[rank];
        marked.assign(faces.size(), false);
        const auto &x = received_points[rank];
        for (unsigned int k = 0; k < bounds.size(); ++k)
          for (const unsigned int f :
               local_mapping(local, faces)->faces_within(x[k], bounds[k]))
            marked[f] = true;
      }
    return exchange_faces(faces, wanted, comm);
  }



  template <int dim>
  std::vector<MasterFace<dim>>
  faces_near(const std::vector<MasterFace<dim>> &faces,
             const std::vector<Point<dim>>      &points,
             const double                        radius,
             const MPI_Comm                      comm)
  {
    // 1. every rank's bounding box of its faces (one box per rank)
    const auto rank_tree = pack_rtree(rank_boxes(faces, comm));

    // 2. each point (with its search box) goes to the ranks whose faces'
    // box it meets
    std::map<unsigned int, std::vector<double>> requests;
    for (const Point<dim> &x : points)
      {
        std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
        rank_tree.query(boost::geometry::index::intersects(
                          search_box(x, radius)),
                        std::back_inserter(hits));
        for (const auto &hit : hits)
          requests[hit.second].insert(requests[hit.second].end(),
                                      x.begin_raw(),
                                      x.end_raw());
      }
    const auto received = Utilities::MPI::some_to_some(comm, requests);

    // 3. each rank answers with its faces whose box meets a requested
    // point's search box, in its own order
    std::map<unsigned int, std::vector<bool>> wanted;
    if (!received.empty())
      {
        std::vector<std::pair<BoundingBox<dim>, unsigned int>> face_boxes;
        for (unsigned int f = 0; f < faces.size(); ++f)
          face_boxes.emplace_back(BoundingBox<dim>(faces[f].vertices), f);
        const auto tree = pack_rtree(face_boxes);
        for (const auto &[rank, coordinates] : received)
          {
            auto &marked = wanted[rank];
            marked.assign(faces.size(), false);
            for (std::size_t i = 0; i + dim <= coordinates.size(); i += dim)
              {
                Point<dim> x;
                for (unsigned int d = 0; d < dim; ++d)
                  x[d] = coordinates[i + d];
                std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
                tree.query(boost::geometry::index::intersects(
                             search_box(x, radius)),
                           std::back_inserter(hits));
                for (const auto &hit : hits)
                  marked[hit.second] = true;
              }
          }
      }
    // 4. the faces near this rank's points, in rank order (as if the
    // whole surface had been gathered and then filtered)
    return exchange_faces(faces, wanted, comm);
  }



  template std::vector<MasterFace<2>>
  closest_faces(const std::vector<MasterFace<2>> &,
                const std::vector<Point<2>> &,
                const MPI_Comm);
  template std::vector<MasterFace<3>>
  closest_faces(const std::vector<MasterFace<3>> &,
                const std::vector<Point<3>> &,
                const MPI_Comm);
  template std::vector<MasterFace<2>>
  faces_near(const std::vector<MasterFace<2>> &,
             const std::vector<Point<2>> &,
             const double,
             const MPI_Comm);
  template std::vector<MasterFace<3>>
  faces_near(const std::vector<MasterFace<3>> &,
             const std::vector<Point<3>> &,
             const double,
             const MPI_Comm);
} // namespace dyncontact
