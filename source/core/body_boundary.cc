// The true boundary of a body in pieces, for the loads on it (Traction):
// lattice cuts of boxes, discs and polygons in 2D, Archimedes' zones of a
// sphere and the lattice cells and strips of a cylinder in 3D.

#include <impm/core/body.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * The parts of [u0, u1] (either order) between the lattice lines
     * u = origin + m spacing.
     */
    std::vector<std::pair<double, double>>
    lattice_cuts(const double u0,
                 const double u1,
                 const double origin,
                 const double spacing)
    {
      std::vector<std::pair<double, double>> parts;
      const double low = std::min(u0, u1), high = std::max(u0, u1);
      double       a = low;
      long m = static_cast<long>(std::floor((low - origin) / spacing)) + 1;
      while (a < high)
        {
          const double b = std::min(high, origin + m * spacing);
          if (b > a)
            parts.emplace_back(a, b);
          a = std::max(a, b);
          ++m;
        }
      return parts;
    }



    /**
     * The area of the disc of radius @p R about the origin within the
     * rectangle [x0, x1] x [y0, y1]: the integral over x of the chord's
     * part between y0 and y1, in closed form between the abscissae where
     * the circle crosses y = y0 or y = y1 (there the integrand changes
     * form).
     */
    double
    disc_in_rectangle(const double R,
                      const double x0,
                      const double x1,
                      const double y0,
                      const double y1)
    {
      const auto half_chord = [&](const double x) {
        return std::sqrt(std::max(0., R * R - x * x));
      };
      // The antiderivative of half_chord.
      const auto integral = [&](const double x) {
        const double c = std::clamp(x, -R, R);
        return 0.5 * (c * half_chord(c) + R * R * std::asin(c / R));
      };
      std::vector<double> breaks = {std::max(x0, -R), std::min(x1, R)};
      if (!(breaks[1] > breaks[0]))
        return 0.;
      for (const double y : {y0, y1})
        if (std::abs(y) < R)
          for (const double x : {-half_chord(y), half_chord(y)})
            if (x > breaks[0] && x < breaks[1])
              breaks.push_back(x);
      std::sort(breaks.begin(), breaks.end());
      double area = 0.;
      for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
        {
          const double a = breaks[k], b = breaks[k + 1];
          const double middle = half_chord(0.5 * (a + b));
          // Which bound is the chord's and which the rectangle's holds
          // between the breaks.
          const bool   upper_is_chord = middle < y1;
          const bool   lower_is_chord = -middle > y0;
          const double upper          = upper_is_chord ? middle : y1;
          const double lower          = lower_is_chord ? -middle : y0;
          if (!(upper > lower))
            continue;
          const double chord_part = integral(b) - integral(a);
          area += (upper_is_chord ? chord_part : y1 * (b - a)) -
                  (lower_is_chord ? -chord_part : y0 * (b - a));
        }
      return area;
    }
  } // namespace



  template <int dim>
  std::vector<typename Body<dim>::BoundaryPiece>
  Body<dim>::boundary_pieces(const unsigned int    axis,
                             const double          sign,
                             const Point<dim>     &origin,
                             const Tensor<1, dim> &spacing) const
  {
    std::vector<BoundaryPiece> pieces;
    if constexpr (dim == 3)
      {
        if (shape == Shape::sphere)
          add_sphere_zones(axis,
                           sign > 0 ? center[axis] : center[axis] - radius,
                           sign > 0 ? center[axis] + radius : center[axis],
                           spacing,
                           pieces);
        else if (shape == Shape::cylinder)
          add_cylinder_pieces(axis, sign, origin, spacing, pieces);
        return pieces;
      }
    const unsigned int j  = dim == 2 ? 1 - axis : 0;
    const auto         at = [&](const double along_axis, const double along_j) {
      Point<dim> x;
      x[axis] = along_axis;
      x[j]    = along_j;
      return x;
    };
    Tensor<1, dim> axis_normal;
    axis_normal[axis] = sign;

    switch (shape)
      {
        case Shape::box:
          {
            const double side =
              sign > 0 ? upper_corner[axis] : lower_corner[axis];
            for (const auto &[a, b] : lattice_cuts(
                   lower_corner[j], upper_corner[j], origin[j], spacing[j]))
              pieces.push_back({at(side, 0.5 * (a + b)), b - a, axis_normal});
            break;
          }
        case Shape::disc:
          {
            // The half circle x_axis = c_axis + sign sqrt(R^2 - (u - c_j)^2).
            const auto angle = [&](const double u) {
              return std::asin(std::clamp((u - center[j]) / radius, -1., 1.));
            };
            for (const auto &[a, b] : lattice_cuts(center[j] - radius,
                                                   center[j] + radius,
                                                   origin[j],
                                                   spacing[j]))
              {
                const double     middle = 0.5 * (angle(a) + angle(b));
                const Point<dim> x =
                  at(center[axis] + sign * radius * std::cos(middle),
                     center[j] + radius * std::sin(middle));
                pieces.push_back(
                  {x, radius * (angle(b) - angle(a)), (x - center) / radius});
              }
            break;
          }
        case Shape::polygon:
          {
            for (const auto &edge : polygon_edges())
              if (sign * edge.normal[axis] > 0.)
                add_edge_pieces(edge, j, origin, spacing, pieces);
            break;
          }
        default:
          break;
      }
    return pieces;
  }



  template <int dim>
  std::vector<typename Body<dim>::BoundaryPiece>
  Body<dim>::boundary_partition(const Point<dim>     &origin,
                                const Tensor<1, dim> &spacing) const
  {
    std::vector<BoundaryPiece> pieces;
    switch (shape)
      {
        case Shape::sphere:
          if constexpr (dim == 3)
            add_sphere_zones(
              2, center[2] - radius, center[2] + radius, spacing, pieces);
          break;
        case Shape::polygon:
          // Each edge cut at the lattice lines across its longer extent.
          for (const auto &edge : polygon_edges())
            add_edge_pieces(
              edge,
              std::abs(edge.tangent[0]) >= std::abs(edge.tangent[1]) ? 0 : 1,
              origin,
              spacing,
              pieces);
          break;
        case Shape::cylinder:
          // Both ends and the two halves of the side: all of it once.
          if constexpr (dim == 3)
            for (const unsigned int axis : {2u, 0u})
              for (const double sign : {1., -1.})
                add_cylinder_pieces(axis, sign, origin, spacing, pieces);
          break;
        case Shape::box:
        case Shape::disc:
          // The sides (half circles) facing up and down, and for a box
          // those facing left and right: each part of the boundary once.
          if (dim == 2)
            for (const unsigned int axis : {1u, 0u})
              for (const double sign : {1., -1.})
                if (axis == 1 || shape == Shape::box)
                  {
                    const auto part =
                      boundary_pieces(axis, sign, origin, spacing);
                    pieces.insert(pieces.end(), part.begin(), part.end());
                  }
          break;
        default:
          break;
      }
    return pieces;
  }



  template <int dim>
  std::vector<typename Body<dim>::PolygonEdge>
  Body<dim>::polygon_edges() const
  {
    std::vector<PolygonEdge> edges;
    if (dim != 2)
      return edges;
    double twice_area = 0.;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      {
        const auto &p = vertices[v];
        const auto &q = vertices[(v + 1) % vertices.size()];
        twice_area += p[0] * q[1] - q[0] * p[1];
      }
    const double orientation = twice_area > 0 ? 1. : -1.;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      {
        PolygonEdge edge;
        edge.start   = vertices[v];
        edge.tangent = vertices[(v + 1) % vertices.size()] - edge.start;
        // Outward normal of a counter-clockwise polygon: (e_y, -e_x).
        edge.normal[0] = orientation * edge.tangent[1];
        edge.normal[1] = -orientation * edge.tangent[0];
        edge.normal /= edge.normal.norm();
        edges.push_back(edge);
      }
    return edges;
  }



  template <int dim>
  void
  Body<dim>::add_edge_pieces(const PolygonEdge          &edge,
                             const unsigned int          j,
                             const Point<dim>           &origin,
                             const Tensor<1, dim>       &spacing,
                             std::vector<BoundaryPiece> &pieces) const
  {
    const double length = edge.tangent.norm();
    for (const auto &[a, b] : lattice_cuts(edge.start[j],
                                           edge.start[j] + edge.tangent[j],
                                           origin[j],
                                           spacing[j]))
      {
        const double t = (0.5 * (a + b) - edge.start[j]) / edge.tangent[j];
        pieces.push_back({Point<dim>(edge.start + t * edge.tangent),
                          length * (b - a) / std::abs(edge.tangent[j]),
                          edge.normal});
      }
  }



  template <int dim>
  void
  Body<dim>::add_sphere_zones(const unsigned int          axis,
                              const double                low,
                              const double                high,
                              const Tensor<1, dim>       &spacing,
                              std::vector<BoundaryPiece> &pieces) const
  {
    // Archimedes: the zone of the sphere between two planes normal to the
    // axis has the area 2 pi R times their distance, whatever its height;
    // cut into equal sectors, every piece has the exact area R du dphi.
    const unsigned int a = (axis + 1) % dim, b = (axis + 2) % dim;
    const unsigned int n_zones =
      std::max(1u,
               static_cast<unsigned int>(
                 std::ceil((high - low) / spacing[axis] - 1e-9)));
    const double du     = (high - low) / n_zones;
    const double finest = std::min(spacing[a], spacing[b]);
    for (unsigned int zone = 0; zone < n_zones; ++zone)
      {
        const double u = low + (zone + 0.5) * du;
        const double r = std::sqrt(
          std::max(0.,
                   radius * radius - (u - center[axis]) * (u - center[axis])));
        // A multiple of four: a quarter model's symmetry planes through the
        // centre fall between sectors.
        const unsigned int n_sectors =
          4u * std::max(1u,
                        static_cast<unsigned int>(
                          std::ceil(2. * M_PI * r / finest / 4. - 1e-9)));
        const double dphi = 2. * M_PI / n_sectors;
        for (unsigned int sector = 0; sector < n_sectors; ++sector)
          {
            const double phi = (sector + 0.5) * dphi;
            Point<dim>   x   = center;
            x[axis]          = u;
            x[a] += r * std::cos(phi);
            x[b] += r * std::sin(phi);
            pieces.push_back({x, radius * du * dphi, (x - center) / radius});
          }
      }
  }


  template <int dim>
  void
  Body<dim>::add_cylinder_pieces(
    [[maybe_unused]] const unsigned int          axis,
    [[maybe_unused]] const double                sign,
    [[maybe_unused]] const Point<dim>           &origin,
    [[maybe_unused]] const Tensor<1, dim>       &spacing,
    [[maybe_unused]] std::vector<BoundaryPiece> &pieces) const
  {
    if constexpr (dim == 3)
      {
        if (axis == 2)
          {
            // The flat end, cut at the lattice lines in x and y: each
            // lattice cell's part of the disc at the cell's centre (a
            // point's place), so a point inside carries its lattice face
            // and one at the rim the part of the disc in its cell.
            Tensor<1, dim> normal;
            normal[2] = sign;
            for (const auto &[x0, x1] : lattice_cuts(center[0] - radius,
                                                     center[0] + radius,
                                                     origin[0],
                                                     spacing[0]))
              for (const auto &[y0, y1] : lattice_cuts(center[1] - radius,
                                                       center[1] + radius,
                                                       origin[1],
                                                       spacing[1]))
                {
                  const double area = disc_in_rectangle(radius,
                                                        x0 - center[0],
                                                        x1 - center[0],
                                                        y0 - center[1],
                                                        y1 - center[1]);
                  if (!(area > 0.))
                    continue;
                  Point<dim> x;
                  x[0] = 0.5 * (x0 + x1);
                  x[1] = 0.5 * (y0 + y1);
                  x[2] = center[2] + (sign > 0 ? height : 0.);
                  pieces.push_back({x, area, normal});
                }
            return;
          }
        // The half of the side facing sign along x or y, from the angle
        // where it starts: an even number of sectors puts the plane
        // through the axis across the half between two of them.
        const double       finest = std::min(spacing[0], spacing[1]);
        const unsigned int n_sectors =
          2 * std::max(1u,
                       static_cast<unsigned int>(
                         std::ceil(M_PI * radius / finest / 2. - 1e-9)));
        const double dphi  = M_PI / n_sectors;
        const double start = axis == 0 ? (sign > 0 ? -0.5 * M_PI : 0.5 * M_PI) :
                                         (sign > 0 ? 0. : M_PI);
        for (const auto &[a, b] :
             lattice_cuts(center[2], center[2] + height, origin[2], spacing[2]))
          for (unsigned int k = 0; k < n_sectors; ++k)
            {
              const double   phi = start + (k + 0.5) * dphi;
              Tensor<1, dim> normal;
              normal[0]    = std::cos(phi);
              normal[1]    = std::sin(phi);
              Point<dim> x = center;
              x[0] += radius * normal[0];
              x[1] += radius * normal[1];
              x[2] = 0.5 * (a + b);
              pieces.push_back({x, radius * dphi * (b - a), normal});
            }
      }
  }



  // The helpers are instantiated through these two.
  template std::vector<Body<2>::BoundaryPiece>
  Body<2>::boundary_pieces(const unsigned int,
                           const double,
                           const Point<2> &,
                           const Tensor<1, 2> &) const;
  template std::vector<Body<3>::BoundaryPiece>
  Body<3>::boundary_pieces(const unsigned int,
                           const double,
                           const Point<3> &,
                           const Tensor<1, 3> &) const;
  template std::vector<Body<2>::BoundaryPiece>
  Body<2>::boundary_partition(const Point<2> &, const Tensor<1, 2> &) const;
  template std::vector<Body<3>::BoundaryPiece>
  Body<3>::boundary_partition(const Point<3> &, const Tensor<1, 3> &) const;
} // namespace impm
