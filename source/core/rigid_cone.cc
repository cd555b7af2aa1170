// A rigid cone on a cylindrical shaft (RigidCone, 3D): its entries, and its
// profile's proximity turned about the axis.
#include <deal.II/base/symmetric_tensor.h>

#include <impm/core/parameters.h>
#include <impm/core/rigid_shapes.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace impm
{
  void
  RigidCone::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Tip",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "Cone (3D): the tip, in m.");
    prm.declare_entry("Axis",
                      "0, 0, 1",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "Cone: the direction from the tip toward the base "
                      "(any length > 0).");
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
    const auto tip_entry  = Parameters::get_vector(prm, name, "Tip", 3);
    const auto axis_entry = Parameters::get_vector(prm, name, "Axis", 3);
    for (unsigned int d = 0; d < 3; ++d)
      {
        tip[d]  = tip_entry[d];
        axis[d] = axis_entry[d];
      }
    if (!(axis.norm() > 0.))
      Parameters::bad_value(name + "/Axis",
                            prm.get("Axis"),
                            "the direction needs a length > 0.");
    axis /= axis.norm();
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
    const double r = radius, h = height, top = h + shaft_length;
    profile = {Point<2>(0., 0.), Point<2>(r, h)};
    if (shaft_length > 0.)
      profile.insert(profile.end(), {Point<2>(r, top), Point<2>(-r, top)});
    profile.push_back(Point<2>(-r, h));
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
} // namespace impm
