// A rigid disc (2D) or sphere (3D) (RigidBall).
#include <deal.II/base/symmetric_tensor.h>

#include <impm/core/rigid_shapes.h>

#include <cmath>
#include <sstream>

namespace impm
{
  template <int dim>
  RigidBall<dim>::RigidBall(const Point<dim> &center, const double radius)
    : center(center)
    , radius(radius)
  {}



  template <int dim>
  typename RigidBall<dim>::Proximity
  RigidBall<dim>::proximity(const Point<dim> &y, const Facing *) const
  {
    Proximity            result;
    const Tensor<1, dim> offset = y - center;
    const double         r      = offset.norm();
    result.gap                  = r - radius;
    if (r == 0.)
      {
        result.normal[0] = 1.;
        return result;
      }
    // n = offset / r and (I - n n) / r, entry by entry with deal.II's
    // operations (a quotient by r is a product with 1 / r): as fast as a
    // single function of all shapes was (the tensor expressions took twice
    // as long here).
    const double inverse = 1. / r;
    for (unsigned int i = 0; i < dim; ++i)
      result.normal[i] = offset[i] * inverse;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        result.normal_derivative[i][j] =
          ((i == j ? 1. : 0.) - result.normal[i] * result.normal[j]) * inverse;
    return result;
  }



  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  RigidBall<dim>::bounding_box() const
  {
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = center[d] - radius;
        upper[d] = center[d] + radius;
      }
    return {lower, upper};
  }



  template <int dim>
  typename RigidBall<dim>::Surface
  RigidBall<dim>::surface() const
  {
    Surface result;
    auto   &corners = result.vertices;
    if (dim == 2)
      {
        const unsigned int n = 64;
        result.faces.emplace_back();
        for (unsigned int i = 0; i < n; ++i)
          {
            const double angle  = 2. * numbers::PI * i / n;
            Point<dim>   vertex = center;
            vertex[0] += radius * std::cos(angle);
            vertex[1] += radius * std::sin(angle);
            corners.push_back(vertex);
            result.faces.back().push_back(i);
          }
        return result;
      }
    const unsigned int n_latitudes = 16, n_longitudes = 32;
    for (unsigned int i = 0; i <= n_latitudes; ++i)
      for (unsigned int j = 0; j < n_longitudes; ++j)
        {
          const double theta  = numbers::PI * i / n_latitudes;
          const double phi    = 2. * numbers::PI * j / n_longitudes;
          Point<dim>   vertex = center;
          vertex[0] += radius * std::sin(theta) * std::cos(phi);
          vertex[1] += radius * std::sin(theta) * std::sin(phi);
          vertex[dim - 1] += radius * std::cos(theta);
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
    return result;
  }



  template <int dim>
  std::string
  RigidBall<dim>::description() const
  {
    std::ostringstream out;
    out << (dim == 2 ? "disc" : "sphere") << " centre (" << center
        << ") radius " << radius;
    return out.str();
  }



  template class RigidBall<2>;
  template class RigidBall<3>;
} // namespace impm
