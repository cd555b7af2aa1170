// The geometry of a rigid body (RigidBody): its pose at a load factor,
// the signed distance, normal and normal derivative of a point
// (proximity), its bounding box and its surface for output. The
// parameters and the description are in rigid_body.cc.
#include <deal.II/base/symmetric_tensor.h>

#include <impm/core/rigid_body.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impm
{
  namespace
  {
    /** Where a point of the plane is relative to a polygon. */
    struct PlanarProximity
    {
      /** Signed distance from the outline, negative inside. */
      double gap;
      /** Outward unit normal at the nearest outline point. */
      Tensor<1, 2> normal;
      /** Its derivative with respect to the point (zero on an edge). */
      Tensor<2, 2> normal_derivative;
    };

    /** The proximity of @p x to the polygon with @p vertices (in order,
     *  either orientation). */
    PlanarProximity
    polygon_proximity(const std::vector<Point<2>> &vertices, const Point<2> &x)
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
      PlanarProximity result;
      result.gap = inside ? -distance : distance;
      if (!at_vertex || distance == 0.)
        {
          result.normal = edge_normal;
          return result;
        }
      // At a vertex the normal turns with the point.
      result.normal = (inside ? nearest - x : x - nearest) / distance;
      result.normal_derivative = (Tensor<2, 2>(unit_symmetric_tensor<2>()) -
                                  outer_product(result.normal, result.normal)) /
                                 result.gap;
      return result;
    }
  } // namespace



  template <int dim>
  Tensor<2, dim>
  RigidBody<dim>::rotation_at(const double load_factor) const
  {
    Tensor<2, dim> rotation = unit_symmetric_tensor<dim>();
    if (!rotates())
      return rotation;
    const double angle = load_factor * rotation_angle;
    const double c = std::cos(angle), s = std::sin(angle);
    if constexpr (dim == 2)
      {
        rotation[0][0] = c;
        rotation[0][1] = -s;
        rotation[1][0] = s;
        rotation[1][1] = c;
      }
    else
      {
        // Rodrigues: R = c I + s [a]x + (1 - c) a a.
        const Tensor<1, dim> &a = rotation_axis;
        rotation                = c * rotation + (1. - c) * outer_product(a, a);
        rotation[0][1] -= s * a[2];
        rotation[0][2] += s * a[1];
        rotation[1][0] += s * a[2];
        rotation[1][2] -= s * a[0];
        rotation[2][0] -= s * a[1];
        rotation[2][1] += s * a[0];
      }
    return rotation;
  }



  template <int dim>
  typename RigidBody<dim>::Proximity
  RigidBody<dim>::proximity(const Point<dim>     &x,
                            const Tensor<1, dim> &body_displacement,
                            const Tensor<2, dim> &rotation,
                            const Facing         *facing) const
  {
    if (!rotates())
      return proximity(x, body_displacement, facing);
    Proximity result = proximity(to_body_frame(x, body_displacement, rotation),
                                 Tensor<1, dim>(),
                                 facing);
    result.normal    = rotation * result.normal;
    result.normal_derivative =
      rotation * result.normal_derivative * transpose(rotation);
    result.overlap_gradient = rotation * result.overlap_gradient;
    return result;
  }



  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  RigidBody<dim>::bounding_box(const Tensor<1, dim> &body_displacement,
                               const double          load_factor) const
  {
    if (!rotates())
      return bounding_box(body_displacement);
    const auto                        box      = bounding_box(Tensor<1, dim>());
    const Tensor<2, dim>              rotation = rotation_at(load_factor);
    std::pair<Point<dim>, Point<dim>> turned;
    for (unsigned int k = 0; k < (1u << dim); ++k)
      {
        Point<dim> corner;
        for (unsigned int d = 0; d < dim; ++d)
          corner[d] = (k >> d) & 1 ? box.second[d] : box.first[d];
        const Point<dim> moved = rotation_centre + body_displacement +
                                 rotation * (corner - rotation_centre);
        for (unsigned int d = 0; d < dim; ++d)
          {
            turned.first[d] =
              k == 0 ? moved[d] : std::min(turned.first[d], moved[d]);
            turned.second[d] =
              k == 0 ? moved[d] : std::max(turned.second[d], moved[d]);
          }
      }
    return turned;
  }



  template <int dim>
  typename RigidBody<dim>::Surface
  RigidBody<dim>::surface(const Tensor<1, dim> &body_displacement,
                          const double          load_factor) const
  {
    if (!rotates())
      return surface(body_displacement);
    Surface              result   = surface(Tensor<1, dim>());
    const Tensor<2, dim> rotation = rotation_at(load_factor);
    for (auto &vertex : result.vertices)
      vertex = rotation_centre + body_displacement +
               rotation * (vertex - rotation_centre);
    return result;
  }



  template <int dim>
  typename RigidBody<dim>::Proximity
  RigidBody<dim>::proximity(const Point<dim>     &x,
                            const Tensor<1, dim> &body_displacement,
                            const Facing         *facing) const
  {
    const Point<dim> y = x - body_displacement;
    Proximity        result;
    using Shape = typename Body<dim>::Shape;
    if constexpr (dim == 3)
      if (surface_mesh)
        {
          const auto mesh          = surface_mesh->proximity(y);
          result.gap               = mesh.gap;
          result.normal            = mesh.normal;
          result.normal_derivative = mesh.normal_derivative;
          return result;
        }
    if (is_cone)
      {
        // The profile's proximity in the plane through the axis and y,
        // turned about the axis: n = n_r e_r + n_z a, and its derivative
        // adds the turning of e_r, (I - a a - e_r e_r) / r.
        const Tensor<1, dim> &a      = cone.axis;
        const Tensor<1, dim>  offset = y - cone.tip;
        const double          z      = offset * a;
        const Tensor<1, dim>  radial = offset - z * a;
        const double          r      = radial.norm();
        Tensor<1, dim>        e_r;
        if (r > 0.)
          e_r = radial / r;
        else
          {
            // On the axis: any direction across it.
            e_r[a[0] * a[0] < 0.5 ? 0 : 1] = 1.;
            e_r -= (e_r * a) * a;
            e_r /= e_r.norm();
          }
        const PlanarProximity planar =
          polygon_proximity(cone.profile, Point<2>(r, z));
        const Tensor<2, 2> &h = planar.normal_derivative;
        result.gap            = planar.gap;
        result.normal         = planar.normal[0] * e_r + planar.normal[1] * a;
        result.normal_derivative =
          outer_product(e_r, h[0][0] * e_r + h[0][1] * a) +
          outer_product(a, h[1][0] * e_r + h[1][1] * a);
        if (r > 0.)
          result.normal_derivative +=
            planar.normal[0] *
            (Tensor<2, dim>(unit_symmetric_tensor<dim>()) -
             outer_product(a, a) - outer_product(e_r, e_r)) /
            r;
        return result;
      }
    if (outline.shape == Shape::box)
      {
        const Point<dim> &a = outline.lower_corner, &b = outline.upper_corner;
        if (facing != nullptr)
          {
            // The sides that oppose the face, in front of which it started
            // the step: the shallowest one that the face overlaps. The face
            // [y_j - l_j, y_j + l_j] in each direction j along the side
            // presses on the part it overlaps, so it leaves or enters
            // contact over an edge gradually.
            double depth = std::numeric_limits<double>::max();
            for (unsigned int d = 0; d < dim; ++d)
              for (const double sign : {-1., 1.})
                {
                  const double plane = sign < 0 ? a[d] : b[d];
                  if (!(sign * facing->normal[d] < 0. &&
                        sign * (facing->start[d] - plane) >=
                          -facing->tolerance))
                    continue;
                  const double to_face = sign * (plane - y[d]);
                  if (to_face < 0. || to_face > b[d] - a[d] || to_face >= depth)
                    continue;
                  double         overlap = 1.;
                  Tensor<1, dim> factors, slopes;
                  // The side, then two bits per direction: which ends of
                  // the face lie inside the side's extent.
                  unsigned int piece = 2 * d + (sign > 0. ? 1 : 0);
                  for (unsigned int j = 0; j < dim; ++j)
                    {
                      factors[j] = 1.;
                      if (j == d)
                        continue;
                      const double l           = facing->half_length[j];
                      const bool   high_inside = y[j] + l < b[j];
                      const bool   low_inside  = y[j] - l > a[j];
                      const double high        = std::min(y[j] + l, b[j]);
                      const double low         = std::max(y[j] - l, a[j]);
                      factors[j] = std::max(high - low, 0.) / (2. * l);
                      if (factors[j] > 0.)
                        slopes[j] =
                          ((high_inside ? 1. : 0.) - (low_inside ? 1. : 0.)) /
                          (2. * l);
                      piece += (1u << (3 + 2 * j)) * (high_inside ? 1 : 0) +
                               (1u << (4 + 2 * j)) * (low_inside ? 1 : 0);
                      overlap *= factors[j];
                    }
                  if (!(overlap > 0.))
                    continue;
                  depth            = to_face;
                  result.gap       = -depth;
                  result.normal    = Tensor<1, dim>();
                  result.normal[d] = sign;
                  result.overlap   = overlap;
                  result.piece     = piece;
                  for (unsigned int j = 0; j < dim; ++j)
                    {
                      double product = slopes[j];
                      for (unsigned int k = 0; k < dim; ++k)
                        if (k != j)
                          product *= factors[k];
                      result.overlap_gradient[j] = product;
                    }
                }
            return result;
          }
        bool inside = true;
        for (unsigned int d = 0; d < dim; ++d)
          inside = inside && y[d] >= a[d] && y[d] <= b[d];
        if (inside)
          {
            // The nearest face: a flat surface.
            double depth = std::numeric_limits<double>::max();
            for (unsigned int d = 0; d < dim; ++d)
              for (const double sign : {-1., 1.})
                {
                  const double to_face = sign < 0 ? y[d] - a[d] : b[d] - y[d];
                  if (to_face < depth)
                    {
                      depth            = to_face;
                      result.normal    = Tensor<1, dim>();
                      result.normal[d] = sign;
                    }
                }
            result.gap = -depth;
            return result;
          }
        // Outside: the nearest point is y clamped to the box.
        Tensor<1, dim> offset;
        Tensor<2, dim> clamped;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double q = std::clamp(y[d], a[d], b[d]);
            offset[d]      = y[d] - q;
            clamped[d][d]  = q != y[d] ? 1. : 0.;
          }
        result.gap    = offset.norm();
        result.normal = offset / result.gap;
        result.normal_derivative =
          (clamped - outer_product(result.normal, result.normal)) / result.gap;
        return result;
      }
    if (outline.shape == Shape::disc || outline.shape == Shape::sphere)
      {
        const Tensor<1, dim> offset = y - outline.center;
        const double         r      = offset.norm();
        result.gap                  = r - outline.radius;
        if (r == 0.)
          {
            result.normal[0] = 1.;
            return result;
          }
        result.normal = offset / r;
        result.normal_derivative =
          (Tensor<2, dim>(unit_symmetric_tensor<dim>()) -
           outer_product(result.normal, result.normal)) /
          r;
        return result;
      }

    // Polygon (2D).
    const auto &vertices = outline.vertices;
    const auto  n        = vertices.size();
    if (facing != nullptr && outline.contains(y))
      {
        // The depth below the nearest edge line of those facing: a flat
        // surface (exact for a convex polygon).
        double twice_area = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            const Point<dim> &p = vertices[i], &q = vertices[(i + 1) % n];
            twice_area += p[0] * q[1] - q[0] * p[1];
          }
        const double orientation = twice_area > 0. ? 1. : -1.;
        double       depth       = std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < n; ++i)
          {
            const Point<dim>    &p = vertices[i], &q = vertices[(i + 1) % n];
            const Tensor<1, dim> edge = q - p;
            Tensor<1, dim>       normal;
            normal[0] = orientation * edge[1] / edge.norm();
            normal[1] = -orientation * edge[0] / edge.norm();
            if (!(normal * facing->normal < 0. &&
                  normal * (facing->start - p) >= -facing->tolerance))
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
    if constexpr (dim == 2)
      {
        const PlanarProximity planar = polygon_proximity(vertices, y);
        result.gap                   = planar.gap;
        result.normal                = planar.normal;
        result.normal_derivative     = planar.normal_derivative;
      }
    return result;
  }



  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  RigidBody<dim>::bounding_box(const Tensor<1, dim> &body_displacement) const
  {
    auto box = outline.bounding_box();
    if constexpr (dim == 3)
      if (surface_mesh)
        box = surface_mesh->bounding_box();
    if (is_cone)
      {
        // The tip and the circles of the base and the shaft's top: a
        // circle of radius R across the axis a reaches R sqrt(1 - a_d^2)
        // along axis d.
        box.first = box.second = cone.tip;
        for (const double z : {cone.height, cone.height + cone.shaft_length})
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double centre = cone.tip[d] + z * cone.axis[d];
              const double reach =
                cone.radius *
                std::sqrt(std::max(1. - cone.axis[d] * cone.axis[d], 0.));
              box.first[d]  = std::min(box.first[d], centre - reach);
              box.second[d] = std::max(box.second[d], centre + reach);
            }
      }
    box.first += body_displacement;
    box.second += body_displacement;
    return box;
  }



  template <int dim>
  typename RigidBody<dim>::Surface
  RigidBody<dim>::surface(const Tensor<1, dim> &body_displacement) const
  {
    Surface result;
    using Shape   = typename Body<dim>::Shape;
    auto &corners = result.vertices;
    if (surface_mesh)
      {
        // The triangles (3D only: the mesh's points are the corners).
        if constexpr (dim == 3)
          corners = surface_mesh->get_vertices();
        for (const auto &triangle : surface_mesh->get_triangles())
          result.faces.push_back({triangle[0], triangle[1], triangle[2]});
      }
    else if (is_cone)
      {
        // The profile's corners off the axis turned about it in 32 steps:
        // the tip, one ring per corner, the centre of the top.
        const unsigned int n_around = 32;
        Tensor<1, dim>     across;
        across[cone.axis[0] * cone.axis[0] < 0.5 ? 0 : 1] = 1.;
        across -= (across * cone.axis) * cone.axis;
        across /= across.norm();
        const Tensor<1, dim> other = cross_product_3d(cone.axis, across);
        const double         top   = cone.height + cone.shaft_length;
        corners.push_back(cone.tip);
        std::vector<double> ring_heights = {cone.height};
        if (cone.shaft_length > 0.)
          ring_heights.push_back(top);
        for (const double z : ring_heights)
          for (unsigned int j = 0; j < n_around; ++j)
            {
              const double angle = 2. * numbers::PI * j / n_around;
              corners.push_back(cone.tip + z * cone.axis +
                                cone.radius * (std::cos(angle) * across +
                                               std::sin(angle) * other));
            }
        corners.push_back(cone.tip + top * cone.axis);
        const unsigned int top_centre = corners.size() - 1;
        const auto ring = [&](const unsigned int k, const unsigned int j) {
          return 1 + k * n_around + j % n_around;
        };
        for (unsigned int j = 0; j < n_around; ++j)
          {
            result.faces.push_back({0, ring(0, j + 1), ring(0, j)});
            if (ring_heights.size() == 2)
              result.faces.push_back(
                {ring(0, j), ring(0, j + 1), ring(1, j + 1), ring(1, j)});
            const unsigned int last = ring_heights.size() - 1;
            result.faces.push_back(
              {top_centre, ring(last, j), ring(last, j + 1)});
          }
      }
    else if (outline.shape == Shape::box)
      {
        const Point<dim> &a = outline.lower_corner, &b = outline.upper_corner;
        // Vertex k has coordinate d from b where bit d of k is set.
        for (unsigned int k = 0; k < (1u << dim); ++k)
          {
            Point<dim> vertex;
            for (unsigned int d = 0; d < dim; ++d)
              vertex[d] = (k >> d) & 1 ? b[d] : a[d];
            corners.push_back(vertex);
          }
        if (dim == 2)
          result.faces = {{0, 1, 3, 2}};
        else
          result.faces = {{0, 2, 6, 4},
                          {1, 5, 7, 3},
                          {0, 4, 5, 1},
                          {2, 3, 7, 6},
                          {0, 1, 3, 2},
                          {4, 6, 7, 5}};
      }
    else if (outline.shape == Shape::polygon)
      {
        corners = outline.vertices;
        result.faces.emplace_back();
        for (unsigned int i = 0; i < corners.size(); ++i)
          result.faces.back().push_back(i);
      }
    else if (dim == 2)
      {
        const unsigned int n = 64;
        result.faces.emplace_back();
        for (unsigned int i = 0; i < n; ++i)
          {
            const double angle  = 2. * numbers::PI * i / n;
            Point<dim>   vertex = outline.center;
            vertex[0] += outline.radius * std::cos(angle);
            vertex[1] += outline.radius * std::sin(angle);
            corners.push_back(vertex);
            result.faces.back().push_back(i);
          }
      }
    else
      {
        const unsigned int n_latitudes = 16, n_longitudes = 32;
        for (unsigned int i = 0; i <= n_latitudes; ++i)
          for (unsigned int j = 0; j < n_longitudes; ++j)
            {
              const double theta  = numbers::PI * i / n_latitudes;
              const double phi    = 2. * numbers::PI * j / n_longitudes;
              Point<dim>   vertex = outline.center;
              vertex[0] += outline.radius * std::sin(theta) * std::cos(phi);
              vertex[1] += outline.radius * std::sin(theta) * std::sin(phi);
              vertex[dim - 1] += outline.radius * std::cos(theta);
              corners.push_back(vertex);
            }
        for (unsigned int i = 0; i < n_latitudes; ++i)
          for (unsigned int j = 0; j < n_longitudes; ++j)
            {
              const unsigned int next = (j + 1) % n_longitudes;
              result.faces.push_back({i * n_longitudes + j,
                                      i * n_longitudes + next,
                                      (i + 1) * n_longitudes + next,
                                      (i + 1) * n_longitudes + j});
            }
      }
    for (auto &vertex : corners)
      vertex += body_displacement;
    return result;
  }



  // The members defined here, for both dimensions (the class's other
  // members are instantiated in rigid_body.cc).
#define IMPM_INSTANTIATE(dim)                                              \
  template Tensor<2, dim> RigidBody<dim>::rotation_at(const double) const; \
  template typename RigidBody<dim>::Proximity RigidBody<dim>::proximity(   \
    const Point<dim> &, const Tensor<1, dim> &, const Facing *) const;     \
  template typename RigidBody<dim>::Proximity RigidBody<dim>::proximity(   \
    const Point<dim> &,                                                    \
    const Tensor<1, dim> &,                                                \
    const Tensor<2, dim> &,                                                \
    const Facing *) const;                                                 \
  template std::pair<Point<dim>, Point<dim>> RigidBody<dim>::bounding_box( \
    const Tensor<1, dim> &) const;                                         \
  template std::pair<Point<dim>, Point<dim>> RigidBody<dim>::bounding_box( \
    const Tensor<1, dim> &, const double) const;                           \
  template typename RigidBody<dim>::Surface RigidBody<dim>::surface(       \
    const Tensor<1, dim> &) const;                                         \
  template typename RigidBody<dim>::Surface RigidBody<dim>::surface(       \
    const Tensor<1, dim> &, const double) const;
  IMPM_INSTANTIATE(2)
  IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE
} // namespace impm
