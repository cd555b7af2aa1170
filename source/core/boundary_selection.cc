#include <deal.II/base/mpi.templates.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/core/boundary_selection.h>
#include <impm/core/parameters.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace impm
{
  namespace
  {
    /** @brief The centre of face @p f of the lattice cell of spacing
     *  @p spacing around @p x. */
    template <int dim>
    Point<dim>
    lattice_face_centre(Point<dim>            x,
                        const unsigned int    f,
                        const Tensor<1, dim> &spacing)
    {
      const unsigned int axis = Names::face_axis(f);
      x[axis] += 0.5 * Names::face_sign(f) * spacing[axis];
      return x;
    }

    /**
     * The part of a 2D boundary piece inside the box [@p lower, @p upper]:
     * the piece is taken as the straight segment through its midpoint
     * along its tangent (normal turned by 90 degrees), size long (exact for
     * a polygon's edges and a box's sides, the chord of a disc's arc), and
     * clipped by the box in both directions (Liang and Barsky). Returns
     * the length inside and the midpoint of that part.
     */
    std::pair<double, Point<2>>
    clip_segment(const Point<2>     &midpoint,
                 const double        length,
                 const Tensor<1, 2> &normal,
                 const Point<2>     &lower,
                 const Point<2>     &upper)
    {
      Tensor<1, 2> tangent;
      tangent[0]               = -normal[1];
      tangent[1]               = normal[0];
      const Point<2>     start = midpoint - 0.5 * length * tangent;
      const Tensor<1, 2> along = length * tangent;
      double             s0 = 0., s1 = 1.;
      for (unsigned int d = 0; d < 2; ++d)
        {
          if (std::abs(along[d]) <= 1e-14 * length)
            {
              if (start[d] < lower[d] || start[d] > upper[d])
                return {0., midpoint};
              continue;
            }
          double a = (lower[d] - start[d]) / along[d];
          double b = (upper[d] - start[d]) / along[d];
          if (a > b)
            std::swap(a, b);
          s0 = std::max(s0, a);
          s1 = std::min(s1, b);
        }
      if (!(s1 > s0))
        return {0., midpoint};
      return {(s1 - s0) * length, start + 0.5 * (s0 + s1) * along};
    }
  } // namespace



  template <int dim>
  void
  BoundarySelection<dim>::declare_parameters(ParameterHandler  &prm,
                                             const std::string &verb)
  {
    prm.declare_entry("Body",
                      "1",
                      Patterns::Integer(1, Body<dim>::max_bodies),
                      "The body whose boundary is " + verb + " (1 to 4).");
    prm.declare_entry("Boundary",
                      "y+",
                      Patterns::Selection("x-|x+|y-|y+|z-|z+|region"),
                      "The side of the body's boundary that is " + verb +
                        ", "
                        "by its outward normal: x-, x+, y-, y+ (, z-, z+); "
                        "x+ is every part whose outward normal has a "
                        "positive x component (n_x > 0: a polygon's slanted "
                        "edges too, a disc's or sphere's half), and so on; "
                        "or 'region': every part of the boundary inside "
                        "the region, whatever its normal (slanted sides).");
    prm.declare_entry("Region lower corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, 3),
                      "If given, only points initially inside this box "
                      "are " +
                        verb +
                        ", and only the boundary inside it: in 2D a side "
                        "is clipped by the box in every direction (the "
                        "length " +
                        verb +
                        " is the side's length inside it); with Boundary = "
                        "region, and in 3D, a piece of the boundary (cut at "
                        "the points' lattice lines) is in when its midpoint "
                        "is (empty: the whole side; required for "
                        "Boundary = region).");
    prm.declare_entry("Region upper corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, 3),
                      "Upper corner of that box.");
  }



  template <int dim>
  BoundarySelection<dim>::BoundarySelection(ParameterHandler  &prm,
                                            const std::string &section)
    : section(section)
    , body(prm.get_integer("Body") - 1)
    , by_region(prm.get("Boundary") == "region")
    , boundary(by_region ? 0 : Names::face_from_name(prm.get("Boundary")))
  {
    const auto lower =
      Parameters::get_optional_vector(prm, section, "Region lower corner", dim);
    const auto upper =
      Parameters::get_optional_vector(prm, section, "Region upper corner", dim);
    if (lower.size() != upper.size())
      Parameters::bad_value(section + "/Region upper corner",
                            prm.get("Region upper corner"),
                            "give both corners of the region, or "
                            "neither.");
    for (unsigned int d = 0; d < lower.size(); ++d)
      {
        region_lower[d] = lower[d];
        region_upper[d] = upper[d];
      }
    has_region = !lower.empty();
    if (by_region && !has_region)
      Parameters::bad_value(section + "/Boundary",
                            "region",
                            "give the region's corners ('Region lower "
                            "corner', 'Region upper corner').");
    if (boundary >= 2 * dim)
      Parameters::bad_value(section + "/Boundary",
                            prm.get("Boundary"),
                            "in " + std::to_string(dim) +
                              "D only x-, x+, y-, y+" +
                              (dim == 3 ? ", z-, z+" : "") + " or region.");
  }



  template <int dim>
  void
  BoundarySelection<dim>::select(
    const std::vector<MaterialPointInfo<dim>> &points,
    const std::vector<Body<dim>>              &bodies,
    const CartesianGrid<dim>                  &grid,
    const MPI_Comm                             communicator)
  {
    if (body >= bodies.size())
      throw InputError("Parameter '" + section +
                       "/Body' = " + std::to_string(body + 1) +
                       " is not allowed: the scene has " +
                       std::to_string(bodies.size()) + " bodies.");
    const Body<dim> &loaded = bodies[body];
    Tensor<1, dim>   spacing;
    for (unsigned int d = 0; d < dim; ++d)
      spacing[d] = grid.cell_size[d] / loaded.points_per_direction;
    // The area of a lattice face normal to each axis.
    std::array<double, dim> lattice_face;
    for (unsigned int a = 0; a < dim; ++a)
      {
        lattice_face[a] = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          if (d != a)
            lattice_face[a] *= spacing[d];
      }

    // The boundary points: those whose lattice
    // neighbour across a loaded face is outside the body, with those faces
    // (a bit per face). A neighbour inside the body but beyond the grid
    // is across a cut (a symmetry plane the body crosses), which carries
    // nothing.
    std::vector<std::pair<std::uint64_t, Point<dim>>> boundary_points;
    std::vector<unsigned int>                         open_faces;
    for (const auto &point : points)
      {
        if (point.body != body)
          continue;
        unsigned int faces = 0;
        for (unsigned int f = 0; f < 2 * dim; ++f)
          {
            if (!by_region && f != boundary)
              continue;
            Point<dim> neighbour = point.initial_position;
            neighbour[Names::face_axis(f)] +=
              Names::face_sign(f) * spacing[Names::face_axis(f)];
            if (!loaded.contains(neighbour))
              faces |= 1u << f;
          }
        if (faces != 0)
          {
            boundary_points.emplace_back(point.id, point.initial_position);
            open_faces.push_back(faces);
          }
      }
    // Points move between processes during the run: every process
    // keeps every loaded point. In the order of the ids, so that ties
    // go the same way on any number of processes.
    std::vector<std::pair<std::pair<std::uint64_t, Point<dim>>, unsigned>>
      local;
    for (unsigned int k = 0; k < boundary_points.size(); ++k)
      local.emplace_back(boundary_points[k], open_faces[k]);
    auto gathered = Utilities::MPI::all_gather(communicator, local);
    local.clear();
    for (const auto &part : gathered)
      local.insert(local.end(), part.begin(), part.end());
    std::sort(local.begin(), local.end(), [](const auto &a, const auto &b) {
      return a.first.first < b.first.first;
    });

    // Each point carries the part of the true boundary nearest to it:
    // the boundary is cut at the lattice lines (a sphere in zones and
    // sectors) and each piece goes to the nearest boundary point, on
    // the face of its domain that the piece's normal points through
    // most, so the loads add up to the traction times the true length
    // or area. Where the body has no pieces (a box in 3D) each point
    // carries its open lattice faces, which are exact: in a region, those
    // whose centre is in it (as a piece is in when its midpoint is).
    point_areas.clear();
    const std::vector<typename Body<dim>::BoundaryPiece> pieces =
      local.empty() ? std::vector<typename Body<dim>::BoundaryPiece>() :
      by_region     ? loaded.boundary_partition(grid.lower, spacing) :
                      loaded.boundary_pieces(Names::face_axis(boundary),
                                         Names::face_sign(boundary),
                                         grid.lower,
                                         spacing);
    if (pieces.empty())
      for (const auto &[point, faces] : local)
        for (unsigned int f = 0; f < 2 * dim; ++f)
          if (faces & (1u << f)) // (in axisymmetry: the face's ring)
            {
              const Point<dim> centre =
                lattice_face_centre(point.second, f, spacing);
              if (in_region(centre))
                point_areas[point.first][f] +=
                  lattice_face[Names::face_axis(f)] * grid.ring_length(centre);
            }
    // The pieces go to the boundary points in the region.
    std::vector<std::pair<std::uint64_t, Point<dim>>> candidates;
    for (const auto &[point, faces] : local)
      if (in_region(point.second))
        candidates.push_back(point);
    if (!candidates.empty())
      add_piece_areas(pieces, candidates, grid);
    if (point_areas.empty())
      throw InputError(section + ": no material point of Body " +
                       std::to_string(body + 1) + " lies on its " +
                       (by_region ?
                          std::string("boundary") :
                          std::string(Names::face(boundary)) + " boundary") +
                       (has_region ? " inside the region" : "") + ".");
    area_sum = 0.;
    for (const auto &entry : point_areas)
      for (const double area : entry.second)
        area_sum += area;
    selected = true;
  }



  template <int dim>
  bool
  BoundarySelection<dim>::in_region(const Point<dim> &x) const
  {
    bool inside = true;
    if (has_region)
      for (unsigned int d = 0; d < dim; ++d)
        inside = inside && x[d] >= region_lower[d] && x[d] <= region_upper[d];
    return inside;
  }



  template <int dim>
  void
  BoundarySelection<dim>::add_piece_areas(
    std::vector<typename Body<dim>::BoundaryPiece>           pieces,
    const std::vector<std::pair<std::uint64_t, Point<dim>>> &candidates,
    const CartesianGrid<dim>                                &grid)
  {
    for (auto &piece : pieces)
      {
        // A body may cross a symmetry plane (a roller face): its part
        // beyond the grid has no points and carries no load. The pieces
        // are cut at lattice lines, among them the grid's faces, so a
        // piece lies wholly inside or outside.
        if (!grid.contains(piece.midpoint))
          continue;
        // A side chosen with a region: in 2D the region clips each piece
        // to its part inside, in every direction (exact for straight
        // sides). Boundary = region, and 3D: a piece is in when its
        // midpoint is (the region then picks slanted sides whose ends
        // lie on other sides).
        bool clipped = false;
        if constexpr (dim == 2)
          if (has_region && !by_region)
            {
              const auto [length, middle] = clip_segment(piece.midpoint,
                                                         piece.size,
                                                         piece.normal,
                                                         region_lower,
                                                         region_upper);
              if (!(length > 0.))
                continue;
              piece.size     = length;
              piece.midpoint = middle;
              clipped        = true;
            }
        if (!clipped && !in_region(piece.midpoint))
          continue;
        const auto nearest =
          std::min_element(candidates.begin(),
                           candidates.end(),
                           [&](const auto &a, const auto &b) {
                             return a.second.distance_square(piece.midpoint) <
                                    b.second.distance_square(piece.midpoint);
                           });
        unsigned int axis = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(piece.normal[d]) > std::abs(piece.normal[axis]))
            axis = d;
        const unsigned int face =
          by_region ? 2 * axis + (piece.normal[axis] > 0. ? 1 : 0) : boundary;
        // In axisymmetry the ring the piece sweeps (exact for a straight
        // piece: 2 pi times its midpoint's radius times its length).
        point_areas[nearest->first][face] +=
          piece.size * grid.ring_length(piece.midpoint);
      }
  }



  template <int dim>
  std::string
  BoundarySelection<dim>::description() const
  {
    return (by_region ? std::string("boundary in the region") :
                        std::string(Names::face(boundary)) + " side") +
           " of Body " + std::to_string(body + 1);
  }



  template <int dim>
  void
  BoundarySelection<dim>::point_areas_are_selected() const
  {
    if (!selected)
      throw std::logic_error("BoundarySelection::areas() before select().");
  }



  template class BoundarySelection<2>;
  template class BoundarySelection<3>;
} // namespace impm
