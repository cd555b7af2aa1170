// A rigid box (RigidBox): flat sides, the exact part of a face over a
// side, and as a turning body a polygon or a surface of triangles.
#include <deal.II/base/symmetric_tensor.h>

#include <impm/core/rigid_shapes.h>

#include <algorithm>
#include <array>
#include <limits>
#include <sstream>

namespace impm
{
  // The two halves of RigidBox::proximity(), as functions of this file
  // alone (not members), which the compiler inlines into it.
  namespace
  {
    /** The proximity of @p y to the box from @p a to @p b without a
     *  facing: inside the nearest side, outside the nearest point of the
     *  box. */
    template <int dim>
    typename RigidShape<dim>::Proximity
    nearest_proximity(const Point<dim> &a,
                      const Point<dim> &b,
                      const Point<dim> &y)
    {
      typename RigidShape<dim>::Proximity result;
      bool                                inside = true;
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



    /** The proximity of @p y to the box from @p a to @p b with a @p
     *  facing: the side that pushes the face, with the face's overlap (none:
     *  not in contact). */
    template <int dim>
    typename RigidShape<dim>::Proximity
    facing_proximity(const Point<dim>                       &a,
                     const Point<dim>                       &b,
                     const Point<dim>                       &y,
                     const typename RigidShape<dim>::Facing &facing)
    {
      typename RigidShape<dim>::Proximity result;
      // The sides that oppose the face, in front of which it started the
      // step: the shallowest one that the face overlaps. The face
      // [y_j - l_j, y_j + l_j] in each direction j along the side presses on
      // the part it overlaps, so it leaves or enters contact over an edge
      // gradually.
      double depth = std::numeric_limits<double>::max();
      for (unsigned int d = 0; d < dim; ++d)
        for (const double sign : {-1., 1.})
          {
            const double plane = sign < 0 ? a[d] : b[d];
            if (!(sign * facing.normal[d] < 0.))
              continue;
            // Over the side: the face's centre within the side's extent
            // (a face straddling the side's edge, beside it, is not).
            const double behind = -sign * (facing.start[d] - plane);
            bool         over   = true;
            for (unsigned int j = 0; j < dim; ++j)
              if (j != d)
                over =
                  over && facing.start[j] >= a[j] && facing.start[j] <= b[j];
            if (behind > (over ? facing.deep_tolerance : facing.tolerance))
              continue;
            const double to_face = sign * (plane - y[d]);
            if (to_face < 0. || to_face > b[d] - a[d] || to_face >= depth)
              continue;
            double         overlap = 1.;
            Tensor<1, dim> factors, slopes;
            // The side, then two bits per direction: which ends of the face
            // lie inside the side's extent.
            unsigned int piece = 2 * d + (sign > 0. ? 1 : 0);
            for (unsigned int j = 0; j < dim; ++j)
              {
                factors[j] = 1.;
                if (j == d)
                  continue;
                const double l           = facing.half_length[j];
                const bool   high_inside = y[j] + l < b[j];
                const bool   low_inside  = y[j] - l > a[j];
                const double high        = std::min(y[j] + l, b[j]);
                const double low         = std::max(y[j] - l, a[j]);
                factors[j]               = std::max(high - low, 0.) / (2. * l);
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
  } // namespace



  template <int dim>
  RigidBox<dim>::RigidBox(const Point<dim> &lower, const Point<dim> &upper)
    : lower(lower)
    , upper(upper)
  {}



  template <int dim>
  typename RigidBox<dim>::Proximity
  RigidBox<dim>::proximity(const Point<dim> &y, const Facing *facing) const
  {
    return facing != nullptr ? facing_proximity(lower, upper, y, *facing) :
                               nearest_proximity(lower, upper, y);
  }



  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  RigidBox<dim>::bounding_box() const
  {
    return {lower, upper};
  }



  template <int dim>
  std::vector<Point<dim>>
  RigidBox<dim>::corners() const
  {
    std::vector<Point<dim>> result;
    for (unsigned int k = 0; k < (1u << dim); ++k)
      {
        Point<dim> corner;
        for (unsigned int d = 0; d < dim; ++d)
          corner[d] = (k >> d) & 1 ? upper[d] : lower[d];
        result.push_back(corner);
      }
    return result;
  }



  template <int dim>
  typename RigidBox<dim>::Surface
  RigidBox<dim>::surface() const
  {
    Surface result;
    result.vertices = corners();
    if (dim == 2)
      result.faces = {{0, 1, 3, 2}};
    else
      result.faces = {{0, 2, 6, 4},
                      {1, 5, 7, 3},
                      {0, 4, 5, 1},
                      {2, 3, 7, 6},
                      {0, 1, 3, 2},
                      {4, 6, 7, 5}};
    return result;
  }



  template <int dim>
  std::string
  RigidBox<dim>::description() const
  {
    std::ostringstream out;
    out << "box [" << lower << "] - [" << upper << "]";
    return out.str();
  }



  template <int dim>
  std::unique_ptr<RigidShape<dim>>
  RigidBox<dim>::turning_form() const
  {
    // A box's exact face overlap is for faces parallel to its sides: a
    // turning box is a polygon or a surface of triangles instead.
    const std::vector<Point<dim>> c = corners();
    if constexpr (dim == 2)
      return std::make_unique<RigidPolygon>(
        std::vector<Point<2>>{c[0], c[1], c[3], c[2]});
    else
      {
        // The sides as quadrilaterals (all ordered alike), two triangles
        // each.
        const std::vector<std::array<unsigned int, 4>> sides = {{{0, 2, 6, 4}},
                                                                {{1, 5, 7, 3}},
                                                                {{0, 4, 5, 1}},
                                                                {{2, 3, 7, 6}},
                                                                {{0, 1, 3, 2}},
                                                                {{4, 6, 7, 5}}};
        std::vector<std::array<unsigned int, 3>>       triangles;
        for (const auto &side : sides)
          {
            triangles.push_back({{side[0], side[1], side[2]}});
            triangles.push_back({{side[0], side[2], side[3]}});
          }
        return std::make_unique<RigidTriangulatedSurface>(
          TriangulatedSurface(c, triangles), "turning box");
      }
  }



  template class RigidBox<2>;
  template class RigidBox<3>;
} // namespace impm
