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
                        "or 'region': every part of the boundary inside "
                        "the region, whatever its normal (slanted sides).");
    prm.declare_entry("Region lower corner",
                      "",
                      Patterns::List(Patterns::Double(), 0, 3),
                      "If given, only points initially inside this box "
                      "are " +
                        verb +
                        " (empty: the whole side; required for "
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

    const auto in_region = [&](const Point<dim> &x) {
      bool inside = true;
      if (has_region)
        for (unsigned int d = 0; d < dim; ++d)
          inside = inside && x[d] >= region_lower[d] && x[d] <= region_upper[d];
      return inside;
    };
    // The boundary points (in the region): those whose lattice
    // neighbour across a loaded face is outside the body or the grid,
    // with those faces (a bit per face).
    std::vector<std::pair<std::uint64_t, Point<dim>>> boundary_points;
    std::vector<unsigned int>                         open_faces;
    for (const auto &point : points)
      {
        if (point.body != body || !in_region(point.initial_position))
          continue;
        unsigned int faces = 0;
        for (unsigned int f = 0; f < 2 * dim; ++f)
          {
            if (!by_region && f != boundary)
              continue;
            Point<dim> neighbour = point.initial_position;
            neighbour[Names::face_axis(f)] +=
              Names::face_sign(f) * spacing[Names::face_axis(f)];
            if (!loaded.contains(neighbour) || !grid.contains(neighbour))
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
    // carries its open lattice faces, which are exact.
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
          if (faces & (1u << f))
            point_areas[point.first][f] += lattice_face[Names::face_axis(f)];
    for (const auto &piece : pieces)
      {
        if (!in_region(piece.midpoint))
          continue;
        const auto nearest = std::min_element(
          local.begin(), local.end(), [&](const auto &a, const auto &b) {
            return a.first.second.distance_square(piece.midpoint) <
                   b.first.second.distance_square(piece.midpoint);
          });
        unsigned int axis = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(piece.normal[d]) > std::abs(piece.normal[axis]))
            axis = d;
        const unsigned int face =
          by_region ? 2 * axis + (piece.normal[axis] > 0. ? 1 : 0) : boundary;
        point_areas[nearest->first.first][face] += piece.size;
      }
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
