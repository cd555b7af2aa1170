// A rigid cone on a cylindrical shaft: its entries; in 3D (RigidCone) its
// profile's proximity turned about the axis, in the meridian plane of an
// axisymmetric grid (RigidConeProfile) the profile's own.
#include <deal.II/base/symmetric_tensor.h>

#include <impm/core/parameters.h>
#include <impm/core/rigid_shapes.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace impm
{
  namespace
  {
    /** The profile of a cone of radius @p r and height @p h on a shaft of
     *  length @p shaft, as (distance from the axis, height above the tip),
     *  mirrored about the axis: a closed polygon. */
    std::vector<Point<2>>
    cone_profile(const double r, const double h, const double shaft)
    {
      const double          top = h + shaft;
      std::vector<Point<2>> profile{Point<2>(0., 0.), Point<2>(r, h)};
      if (shaft > 0.)
        profile.insert(profile.end(), {Point<2>(r, top), Point<2>(-r, top)});
      profile.push_back(Point<2>(-r, h));
      return profile;
    }



    /** Read and check 'Cone radius', 'Cone height' and 'Shaft length'. */
    void
    read_sizes(const ParameterHandler &prm,
               const std::string      &name,
               double                 &radius,
               double                 &height,
               double                 &shaft_length)
    {
      height       = prm.get_double("Cone height");
      radius       = prm.get_double("Cone radius");
      shaft_length = prm.get_double("Shaft length");
      if (!(height > 0.))
        Parameters::bad_value(name + "/Cone height",
                              prm.get("Cone height"),
                              "it must be > 0.");
      if (!(radius > 0.))
        Parameters::bad_value(name + "/Cone radius",
                              prm.get("Cone radius"),
                              "it must be > 0.");
    }
  } // namespace



  void
  RigidCone::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Tip",
                      "",
                      Patterns::List(Patterns::Double(), 0, 3),
                      "Cone: the tip, in m; empty: the origin (in 2D, the "
                      "meridian plane of an axisymmetric grid: on the "
                      "axis, x = 0).");
    prm.declare_entry("Axis",
                      "",
                      Patterns::List(Patterns::Double(), 0, 3),
                      "Cone: the direction from the tip toward the base "
                      "(any length > 0; in 2D along the axis: 0, 1 or 0, "
                      "-1); empty: +z (3D), +y (2D).");
    prm.declare_entry("Cone height",
                      "1",
                      Patterns::Double(0.),
                      "Cone: the height from the tip to the base, in m "
                      "(> 0).");
    prm.declare_entry("Cone radius",
                      "0.5",
                      Patterns::Double(0.),
                      "Cone: the radius of the base and the shaft, in m "
                      "(> 0).");
    prm.declare_entry("Shaft length",
                      "0",
                      Patterns::Double(0.),
                      "Cone: the length of the cylindrical shaft above "
                      "the base, in m (>= 0; 0: a cone alone).");
  }



  RigidCone::RigidCone(ParameterHandler &prm, const std::string &name)
  {
    const auto tip_entry = Parameters::get_optional_vector(prm, name, "Tip", 3);
    const auto axis_entry =
      Parameters::get_optional_vector(prm, name, "Axis", 3);
    axis[2] = 1.;
    for (unsigned int d = 0; d < 3; ++d)
      {
        if (!tip_entry.empty())
          tip[d] = tip_entry[d];
        if (!axis_entry.empty())
          axis[d] = axis_entry[d];
      }
    if (!(axis.norm() > 0.))
      Parameters::bad_value(name + "/Axis",
                            prm.get("Axis"),
                            "the direction needs a length > 0.");
    axis /= axis.norm();
    read_sizes(prm, name, radius, height, shaft_length);
    profile = cone_profile(radius, height, shaft_length);
  }



  RigidCone::Proximity
  RigidCone::proximity(const Point<3> &y, const Facing *) const
  {
    // The profile's proximity in the plane through the axis and y, turned
    // about the axis: n = n_r e_r + n_z a, and its derivative adds the
    // turning of e_r, (I - a a - e_r e_r) / r.
    Proximity           result;
    const Tensor<1, 3> &a      = axis;
    const Tensor<1, 3>  offset = y - tip;
    const double        z      = offset * a;
    const Tensor<1, 3>  radial = offset - z * a;
    const double        r      = radial.norm();
    Tensor<1, 3>        e_r;
    if (r > 0.)
      e_r = radial / r;
    else
      {
        // On the axis: any direction across it.
        e_r[a[0] * a[0] < 0.5 ? 0 : 1] = 1.;
        e_r -= (e_r * a) * a;
        e_r /= e_r.norm();
      }
    const RigidPolygon::Proximity planar =
      RigidPolygon::planar_proximity(profile, Point<2>(r, z));
    const Tensor<2, 2> &h    = planar.normal_derivative;
    result.gap               = planar.gap;
    result.normal            = planar.normal[0] * e_r + planar.normal[1] * a;
    result.normal_derivative = outer_product(e_r, h[0][0] * e_r + h[0][1] * a) +
                               outer_product(a, h[1][0] * e_r + h[1][1] * a);
    if (r > 0.)
      result.normal_derivative +=
        planar.normal[0] *
        (Tensor<2, 3>(unit_symmetric_tensor<3>()) - outer_product(a, a) -
         outer_product(e_r, e_r)) /
        r;
    return result;
  }



  std::pair<Point<3>, Point<3>>
  RigidCone::bounding_box() const
  {
    // The tip and the circles of the base and the shaft's top: a circle of
    // radius R across the axis a reaches R sqrt(1 - a_d^2) along axis d.
    std::pair<Point<3>, Point<3>> box(tip, tip);
    for (const double z : {height, height + shaft_length})
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double centre = tip[d] + z * axis[d];
          const double reach =
            radius * std::sqrt(std::max(1. - axis[d] * axis[d], 0.));
          box.first[d]  = std::min(box.first[d], centre - reach);
          box.second[d] = std::max(box.second[d], centre + reach);
        }
    return box;
  }



  RigidCone::Surface
  RigidCone::surface() const
  {
    // The profile's corners off the axis turned about it in 32 steps: the
    // tip, one ring per corner, the centre of the top.
    Surface            result;
    auto              &corners  = result.vertices;
    const unsigned int n_around = 32;
    Tensor<1, 3>       across;
    across[axis[0] * axis[0] < 0.5 ? 0 : 1] = 1.;
    across -= (across * axis) * axis;
    across /= across.norm();
    const Tensor<1, 3> other = cross_product_3d(axis, across);
    const double       top   = height + shaft_length;
    corners.push_back(tip);
    std::vector<double> ring_heights = {height};
    if (shaft_length > 0.)
      ring_heights.push_back(top);
    for (const double z : ring_heights)
      for (unsigned int j = 0; j < n_around; ++j)
        {
          const double angle = 2. * numbers::PI * j / n_around;
          corners.push_back(
            tip + z * axis +
            radius * (std::cos(angle) * across + std::sin(angle) * other));
        }
    corners.push_back(tip + top * axis);
    const unsigned int top_centre = corners.size() - 1;
    const auto         ring = [&](const unsigned int k, const unsigned int j) {
      return 1 + k * n_around + j % n_around;
    };
    for (unsigned int j = 0; j < n_around; ++j)
      {
        result.faces.push_back({0, ring(0, j + 1), ring(0, j)});
        if (ring_heights.size() == 2)
          result.faces.push_back(
            {ring(0, j), ring(0, j + 1), ring(1, j + 1), ring(1, j)});
        const unsigned int last = ring_heights.size() - 1;
        result.faces.push_back({top_centre, ring(last, j), ring(last, j + 1)});
      }
    return result;
  }



  std::string
  RigidCone::description() const
  {
    std::ostringstream out;
    out << "cone tip (" << tip << ") axis (" << axis << ") height " << height
        << " radius " << radius << " shaft " << shaft_length;
    return out.str();
  }



  RigidConeProfile::RigidConeProfile(ParameterHandler  &prm,
                                     const std::string &name)
  {
    auto tip_entry  = Parameters::get_optional_vector(prm, name, "Tip", 2);
    auto axis_entry = Parameters::get_optional_vector(prm, name, "Axis", 2);
    if (tip_entry.empty())
      tip_entry = {0., 0.};
    if (axis_entry.empty())
      axis_entry = {0., 1.};
    tip = Point<2>(tip_entry[0], tip_entry[1]);
    if (tip[0] != 0.)
      Parameters::bad_value(name + "/Tip",
                            prm.get("Tip"),
                            "a cone in 2D is the meridian plane of an "
                            "axisymmetric one: its tip lies on the axis, x = "
                            "0.");
    if (!(axis_entry[0] == 0. && axis_entry[1] != 0.))
      Parameters::bad_value(name + "/Axis",
                            prm.get("Axis"),
                            "a cone in 2D turns about the grid's axis: its "
                            "axis is 0, 1 or 0, -1.");
    direction = axis_entry[1] > 0. ? 1. : -1.;
    read_sizes(prm, name, radius, height, shaft_length);
    profile = cone_profile(radius, height, shaft_length);
  }



  RigidConeProfile::Proximity
  RigidConeProfile::proximity(const Point<2> &y, const Facing *) const
  {
    // The profile's coordinates (r, height above the tip) are (x, direction
    // (y - tip)): the normal's second component and the derivative's mixed
    // ones change sign with the direction.
    const RigidPolygon::Proximity planar = RigidPolygon::planar_proximity(
      profile, Point<2>(y[0], direction * (y[1] - tip[1])));
    Proximity result;
    result.gap                     = planar.gap;
    result.piece                   = planar.piece;
    result.normal[0]               = planar.normal[0];
    result.normal[1]               = direction * planar.normal[1];
    const Tensor<2, 2> &h          = planar.normal_derivative;
    result.normal_derivative[0][0] = h[0][0];
    result.normal_derivative[0][1] = direction * h[0][1];
    result.normal_derivative[1][0] = direction * h[1][0];
    result.normal_derivative[1][1] = h[1][1];
    return result;
  }



  std::pair<Point<2>, Point<2>>
  RigidConeProfile::bounding_box() const
  {
    const double far = tip[1] + direction * (height + shaft_length);
    return {Point<2>(-radius, std::min(tip[1], far)),
            Point<2>(radius, std::max(tip[1], far))};
  }



  RigidConeProfile::Surface
  RigidConeProfile::surface() const
  {
    // The profile's side x >= 0 from the tip: (0, 0), (r, h), and the
    // shaft's (r, top), (0, top) or the base's centre (0, h).
    Surface               result;
    const double          top = height + shaft_length;
    std::vector<Point<2>> corners{Point<2>(0., 0.), Point<2>(radius, height)};
    if (shaft_length > 0.)
      corners.insert(corners.end(), {Point<2>(radius, top), Point<2>(0., top)});
    else
      corners.push_back(Point<2>(0., height));
    for (const Point<2> &corner : corners)
      result.vertices.emplace_back(corner[0], tip[1] + direction * corner[1]);
    result.faces.emplace_back();
    for (unsigned int i = 0; i < result.vertices.size(); ++i)
      result.faces.back().push_back(i);
    return result;
  }



  std::string
  RigidConeProfile::description() const
  {
    std::ostringstream out;
    out << "cone in the meridian plane, tip (" << tip << ") axis (0, "
        << direction << ") height " << height << " radius " << radius
        << " shaft " << shaft_length;
    return out.str();
  }
} // namespace impm
