// A rigid polygon (RigidPolygon, 2D), and the proximity of a point to a
// polygon in the plane, which the cone's profile uses too.
#include <deal.II/base/symmetric_tensor.h>

#include <impm/core/rigid_shapes.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace impm
{
  RigidPolygon::RigidPolygon(const std::vector<Point<2>> &vertices)
    : vertices(vertices)
  {}



  RigidPolygon::Proximity
  RigidPolygon::planar_proximity(const std::vector<Point<2>> &vertices,
                                 const Point<2>              &x)
  {
    const auto n          = vertices.size();
    double     twice_area = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<2> &p = vertices[i], &q = vertices[(i + 1) % n];
        twice_area += p[0] * q[1] - q[0] * p[1];
      }
    const double orientation = twice_area > 0. ? 1. : -1.;
    double       distance    = std::numeric_limits<double>::max();
    bool         at_vertex = false, inside = false;
    Point<2>     nearest;
    Tensor<1, 2> edge_normal;
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<2>    &p = vertices[i], &q = vertices[(i + 1) % n];
        const Tensor<1, 2> edge = q - p;
        const double       s =
          std::clamp(((x - p) * edge) / edge.norm_square(), 0., 1.);
        const Point<2> on_edge = p + s * edge;
        const double   d       = x.distance(on_edge);
        if (d < distance)
          {
            distance       = d;
            nearest        = on_edge;
            at_vertex      = s == 0. || s == 1.;
            edge_normal[0] = orientation * edge[1] / edge.norm();
            edge_normal[1] = -orientation * edge[0] / edge.norm();
          }
        // Even-odd rule, as Body::contains().
        if ((p[1] > x[1]) != (q[1] > x[1]) &&
            x[0] < (q[0] - p[0]) * (x[1] - p[1]) / (q[1] - p[1]) + p[0])
          inside = !inside;
      }
    Proximity result;
    result.gap = inside ? -distance : distance;
    if (!at_vertex || distance == 0.)
      {
        result.normal = edge_normal;
        return result;
      }
    // At a vertex the normal turns with the point.
    result.normal            = (inside ? nearest - x : x - nearest) / distance;
    result.normal_derivative = (Tensor<2, 2>(unit_symmetric_tensor<2>()) -
                                outer_product(result.normal, result.normal)) /
                               result.gap;
    return result;
  }



  RigidPolygon::Proximity
  RigidPolygon::proximity(const Point<2> &y, const Facing *facing) const
  {
    if (facing == nullptr || !contains(y))
      return planar_proximity(vertices, y);
    // The depth below the nearest edge line of those facing: a flat
    // surface (exact for a convex polygon).
    Proximity  result;
    const auto n          = vertices.size();
    double     twice_area = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<2> &p = vertices[i], &q = vertices[(i + 1) % n];
        twice_area += p[0] * q[1] - q[0] * p[1];
      }
    const double orientation = twice_area > 0. ? 1. : -1.;
    double       depth       = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<2>    &p = vertices[i], &q = vertices[(i + 1) % n];
        const Tensor<1, 2> edge = q - p;
        Tensor<1, 2>       normal;
        normal[0] = orientation * edge[1] / edge.norm();
        normal[1] = -orientation * edge[0] / edge.norm();
        if (!(normal * facing->normal < 0.))
          continue;
        // Over the edge: the start's projection on it within its ends.
        const double along  = (facing->start - p) * edge / edge.norm_square();
        const double behind = -(normal * (facing->start - p));
        if (behind > (along >= 0. && along <= 1. ? facing->deep_tolerance :
                                                   facing->tolerance))
          continue;
        const double to_edge = normal * (p - y);
        if (to_edge >= 0. && to_edge < depth)
          {
            depth         = to_edge;
            result.normal = normal;
            result.piece  = i;
          }
      }
    if (depth < std::numeric_limits<double>::max())
      result.gap = -depth;
    return result;
  }



  bool
  RigidPolygon::contains(const Point<2> &x) const
  {
    // Body::contains()'s even-odd rule, in its order of the edges.
    bool inside = false;
    for (unsigned int i = 0, j = vertices.size() - 1; i < vertices.size();
         j = i++)
      {
        const Point<2> &a = vertices[i], &b = vertices[j];
        if ((a[1] > x[1]) != (b[1] > x[1]) &&
            x[0] < (b[0] - a[0]) * (x[1] - a[1]) / (b[1] - a[1]) + a[0])
          inside = !inside;
      }
    return inside;
  }



  std::pair<Point<2>, Point<2>>
  RigidPolygon::bounding_box() const
  {
    Point<2> lower = vertices[0], upper = vertices[0];
    for (const auto &vertex : vertices)
      for (unsigned int d = 0; d < 2; ++d)
        {
          lower[d] = std::min(lower[d], vertex[d]);
          upper[d] = std::max(upper[d], vertex[d]);
        }
    return {lower, upper};
  }



  RigidPolygon::Surface
  RigidPolygon::surface() const
  {
    Surface result;
    result.vertices = vertices;
    result.faces.emplace_back();
    for (unsigned int i = 0; i < vertices.size(); ++i)
      result.faces.back().push_back(i);
    return result;
  }



  std::string
  RigidPolygon::description() const
  {
    std::ostringstream out;
    out << "polygon with " << vertices.size() << " vertices";
    return out.str();
  }
} // namespace impm
