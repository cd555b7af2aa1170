// The geometry of a rigid body (RigidBody): its pose at a load factor, and
// its shape's (RigidShape) proximity, bounding box and surface moved and
// turned with it. The parameters and the description are in rigid_body.cc,
// the shapes in rigid_shape.cc and one file each.
#include <deal.II/base/symmetric_tensor.h>

#include <impm/core/rigid_body.h>

#include <algorithm>
#include <cmath>

namespace impm
{
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
  std::pair<Point<dim>, Point<dim>>
  RigidBody<dim>::bounding_box(const Tensor<1, dim> &body_displacement) const
  {
    auto box = shape->bounding_box();
    box.first += body_displacement;
    box.second += body_displacement;
    return box;
  }



  template <int dim>
  typename RigidBody<dim>::Surface
  RigidBody<dim>::surface(const Tensor<1, dim> &body_displacement) const
  {
    Surface result = shape->surface();
    for (auto &vertex : result.vertices)
      vertex += body_displacement;
    return result;
  }



  // The members defined here, for both dimensions (the class's other
  // members are instantiated in rigid_body.cc).
#define IMPM_INSTANTIATE(dim)                                              \
  template Tensor<2, dim> RigidBody<dim>::rotation_at(const double) const; \
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
