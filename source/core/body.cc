#include <deal.II/base/utilities.h>

#include <impm/core/body.h>
#include <impm/core/parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace impm
{
  template <int dim>
  void
  Body<dim>::declare_shape_parameters(ParameterHandler  &prm,
                                      const std::string &extra_shapes)
  {
    prm.declare_entry(
      "Shape",
      "box",
      Patterns::Selection("box|disc|sphere|polygon|cylinder" + extra_shapes),
      "Shape of the region: box (2D, 3D), "
      "disc (2D), sphere (3D), polygon (2D) or cylinder (3D, material "
      "bodies: its axis along z, from its base centre 'Center' up by "
      "'Height'; an axisymmetric scene's 3D counterpart)" +
        (extra_shapes.empty() ?
           std::string(".") :
           ", or, for rigid bodies, cone (3D, or its meridian plane in an "
           "axisymmetric 2D grid) or stl (3D)."));
    prm.declare_entry("Lower corner",
                      "0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Box: lower corner, one coordinate per dimension, "
                      "in m.");
    prm.declare_entry("Upper corner",
                      "1, 1",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Box: upper corner, in m.");
    prm.declare_entry("Center",
                      "0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Disc or sphere: centre; cylinder: the centre of "
                      "its base; in m.");
    prm.declare_entry("Radius",
                      "1",
                      Patterns::Double(0.),
                      "Disc, sphere or cylinder: radius in m (> 0).");
    prm.declare_entry("Height",
                      "1",
                      Patterns::Double(0.),
                      "Cylinder: height along z in m (> 0).");
    prm.declare_entry("Vertices",
                      "0, 0; 1, 0; 0, 1",
                      Patterns::Anything(),
                      "Polygon (2D): vertices 'x, y; x, y; ...' in order "
                      "(at least three).");
  }



  template <int dim>
  void
  Body<dim>::declare_parameters(ParameterHandler &prm)
  {
    for (unsigned int k = 1; k <= max_bodies; ++k)
      {
        prm.enter_subsection("Body " + std::to_string(k));
        declare_shape_parameters(prm);
        prm.declare_entry("Points per cell direction",
                          "2",
                          Patterns::Integer(1, 10),
                          "n: each cell the body fills holds up to n^dim "
                          "regularly placed material points (1 to 10). "
                          "With 1 a cell's hourglass modes have no "
                          "stiffness: GMRES with AMG may not converge.");
        prm.declare_entry("Density",
                          "1000",
                          Patterns::Double(0.),
                          "Initial density rho_0 in kg/m^3 (>= 0).");
        prm.declare_entry("Initial stress",
                          "zero",
                          Patterns::Selection("zero|geostatic"),
                          "The stress the body starts from: zero, or "
                          "geostatic (vertical stress from the weight of the "
                          "material above a point, see Surface level; "
                          "horizontal stress K0 times "
                          "that; needs gravity along the last axis, acting "
                          "from the first load step: Gravity/Ramped = "
                          "false).");
        prm.declare_entry("K0",
                          "0.5",
                          Patterns::Double(0., 10.),
                          "Geostatic start: ratio of horizontal to vertical "
                          "stress, in [0, 10] (nu/(1 - nu) for a laterally "
                          "confined elastic layer).");
        prm.declare_entry("Surface level",
                          "",
                          Patterns::Anything(),
                          "Geostatic start: empty, the vertical stress at a "
                          "point is the weight of the material above it (of "
                          "every body, each with its density), so that "
                          "layers, slopes and a body on another start from "
                          "what they carry; or the elevation (last "
                          "coordinate) of a horizontal free surface, and the "
                          "vertical stress is this body's density times g "
                          "times the depth below it (a surface above the "
                          "body's top stands for an overburden the scene "
                          "does not model: load the top with a traction "
                          "equal to its weight).");
        prm.enter_subsection("Material");
        MaterialRegistry::declare_parameters(prm);
        prm.leave_subsection();
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  Body<dim>::parse_shape(ParameterHandler &prm)
  {
    shape = static_cast<Shape>(Parameters::selection_index(shape_names,
                                                           name + "/Shape",
                                                           prm.get("Shape")));
    if ((shape == Shape::disc || shape == Shape::polygon) && dim != 2)
      Parameters::bad_value(name + "/Shape",
                            prm.get("Shape"),
                            "in 3D only box, sphere or cylinder.");
    if ((shape == Shape::sphere || shape == Shape::cylinder) && dim != 3)
      Parameters::bad_value(name + "/Shape",
                            prm.get("Shape"),
                            "in 2D only box, disc or polygon.");
    if (shape == Shape::box)
      {
        const auto lower =
          Parameters::get_vector(prm, name, "Lower corner", dim);
        const auto upper =
          Parameters::get_vector(prm, name, "Upper corner", dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower_corner[d] = lower[d];
            upper_corner[d] = upper[d];
            if (!(upper[d] > lower[d]))
              Parameters::bad_value(
                name + "/Upper corner",
                prm.get("Upper corner"),
                "each coordinate must exceed that of 'Lower corner' (" +
                  prm.get("Lower corner") + ").");
          }
      }
    else if (shape == Shape::disc || shape == Shape::sphere ||
             shape == Shape::cylinder)
      {
        const auto c = Parameters::get_vector(prm, name, "Center", dim);
        for (unsigned int d = 0; d < dim; ++d)
          center[d] = c[d];
        radius = prm.get_double("Radius");
        if (!(radius > 0.))
          Parameters::bad_value(name + "/Radius",
                                prm.get("Radius"),
                                "it must be > 0.");
        height = prm.get_double("Height");
        if (shape == Shape::cylinder && !(height > 0.))
          Parameters::bad_value(name + "/Height",
                                prm.get("Height"),
                                "it must be > 0.");
      }
    else
      {
        vertices.clear();
        for (const auto &xy :
             Parameters::get_point_list(prm, name, "Vertices", 2))
          {
            Point<dim> p;
            p[0] = xy[0];
            p[1] = xy[1];
            vertices.push_back(p);
          }
        if (vertices.size() < 3)
          Parameters::bad_value(name + "/Vertices",
                                prm.get("Vertices"),
                                "a polygon needs at least three vertices.");
        check_polygon(prm.get("Vertices"));
      }
  }



  template <int dim>
  void
  Body<dim>::parse_parameters(ParameterHandler &prm, const unsigned int number)
  {
    name = "Body " + std::to_string(number);
    prm.enter_subsection(name);
    parse_shape(prm);
    points_per_direction         = prm.get_integer("Points per cell direction");
    density                      = prm.get_double("Density");
    initial_stress.geostatic     = prm.get("Initial stress") == "geostatic";
    initial_stress.k0            = prm.get_double("K0");
    const std::string level      = Utilities::trim(prm.get("Surface level"));
    initial_stress.surface_named = !level.empty();
    if (initial_stress.surface_named)
      try
        {
          std::size_t end              = 0;
          initial_stress.surface_level = std::stod(level, &end);
          if (end != level.size() ||
              !std::isfinite(initial_stress.surface_level))
            throw std::invalid_argument(level);
        }
      catch (const std::exception &)
        {
          Parameters::bad_value(name + "/Surface level",
                                level,
                                "a number (the elevation of the surface), or "
                                "empty for the top of the body.");
        }
    prm.enter_subsection("Material");
    material = MaterialRegistry::create(prm, name + "/Material");
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  double
  Body<dim>::height_inside_above(const Point<dim> &x) const
  {
    const unsigned int up = dim - 1;
    // The line's piece [bottom, top] inside a convex shape, or none.
    const auto above = [&x, up](const double bottom, const double top) {
      return std::max(top - std::max(bottom, x[up]), 0.);
    };
    if (shape == Shape::box)
      {
        for (unsigned int d = 0; d < up; ++d)
          if (!(x[d] >= lower_corner[d] && x[d] <= upper_corner[d]))
            return 0.;
        return above(lower_corner[up], upper_corner[up]);
      }
    double off_axis_squared = 0.;
    for (unsigned int d = 0; d < up; ++d)
      off_axis_squared += (x[d] - center[d]) * (x[d] - center[d]);
    if (shape == Shape::disc || shape == Shape::sphere)
      {
        if (off_axis_squared >= radius * radius)
          return 0.;
        const double half = std::sqrt(radius * radius - off_axis_squared);
        return above(center[up] - half, center[up] + half);
      }
    if (shape == Shape::cylinder)
      return off_axis_squared < radius * radius ?
               above(center[up], center[up] + height) :
               0.;
    // Polygon: the heights where the vertical line crosses the edges (each
    // edge half-open in x, as in contains()), paired bottom to top.
    std::vector<double> crossings;
    for (unsigned int i = 0, j = vertices.size() - 1; i < vertices.size();
         j = i++)
      {
        const Point<dim> &a = vertices[i], &b = vertices[j];
        if ((a[0] > x[0]) != (b[0] > x[0]))
          crossings.push_back(a[1] +
                              (b[1] - a[1]) * (x[0] - a[0]) / (b[0] - a[0]));
      }
    std::sort(crossings.begin(), crossings.end());
    double height = 0.;
    for (unsigned int k = 0; k + 1 < crossings.size(); k += 2)
      height += above(crossings[k], crossings[k + 1]);
    return height;
  }



  template <int dim>
  SymmetricTensor<2, 3>
  Body<dim>::geostatic_stress(const Point<dim>             &x,
                              const double                  g,
                              const std::vector<Body<dim>> &bodies) const
  {
    double overburden = 0.;
    if (initial_stress.surface_named)
      overburden =
        density * std::max(initial_stress.surface_level - x[dim - 1], 0.);
    else
      for (const Body<dim> &body : bodies)
        overburden += body.density * body.height_inside_above(x);
    const double          vertical = -g * overburden;
    SymmetricTensor<2, 3> stress;
    for (unsigned int d = 0; d < 3; ++d)
      stress[d][d] = initial_stress.k0 * vertical;
    stress[dim - 1][dim - 1] = vertical;
    return stress;
  }



  namespace
  {
    /** Twice the signed area of the triangle a, b, c (2D). */
    template <int dim>
    double
    orientation(const Point<dim> &a, const Point<dim> &b, const Point<dim> &c)
    {
      return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }

    /** Whether the closed segments a-b and c-d share a point (2D). */
    template <int dim>
    bool
    segments_meet(const Point<dim> &a,
                  const Point<dim> &b,
                  const Point<dim> &c,
                  const Point<dim> &d)
    {
      const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
      const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
      if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) &&
          ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return true;
      // Collinear touching.
      const auto on_segment =
        [](const Point<dim> &p, const Point<dim> &q, const Point<dim> &r) {
          return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) &&
                 std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
        };
      return (o1 == 0 && on_segment(a, b, c)) ||
             (o2 == 0 && on_segment(a, b, d)) ||
             (o3 == 0 && on_segment(c, d, a)) ||
             (o4 == 0 && on_segment(c, d, b));
    }
  } // namespace



  template <int dim>
  void
  Body<dim>::check_polygon(const std::string &value) const
  {
    const unsigned int n = vertices.size();
    // Coincident neighbours first: their edge of no length would otherwise
    // be reported as crossing the edges next to it.
    for (unsigned int i = 0; i < n; ++i)
      if (const unsigned int next = (i + 1) % n;
          vertices[i].distance(vertices[next]) == 0.)
        Parameters::bad_value(
          name + "/Vertices",
          value,
          "vertices " + std::to_string(std::min(i, next) + 1) + " and " +
            std::to_string(std::max(i, next) + 1) + " coincide.");
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        {
          // Edges i and j are neighbours if they share a vertex.
          if (j == i + 1 || (i == 0 && j == n - 1))
            continue;
          if (segments_meet(vertices[i],
                            vertices[(i + 1) % n],
                            vertices[j],
                            vertices[(j + 1) % n]))
            Parameters::bad_value(name + "/Vertices",
                                  value,
                                  "the polygon's edges " +
                                    std::to_string(i + 1) + " and " +
                                    std::to_string(j + 1) +
                                    " cross (give the vertices in order "
                                    "around the boundary).");
        }
    if (volume() == 0.)
      Parameters::bad_value(name + "/Vertices",
                            value,
                            "the polygon has no area.");
  }



  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  Body<dim>::bounding_box() const
  {
    if (shape == Shape::box)
      return {lower_corner, upper_corner};
    Point<dim> lower, upper;
    if (shape == Shape::disc || shape == Shape::sphere ||
        shape == Shape::cylinder)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = center[d] - radius;
            upper[d] = center[d] + radius;
          }
        if (shape == Shape::cylinder)
          {
            lower[dim - 1] = center[dim - 1];
            upper[dim - 1] = center[dim - 1] + height;
          }
      }
    else
      {
        lower = upper = vertices[0];
        for (const auto &vertex : vertices)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], vertex[d]);
              upper[d] = std::max(upper[d], vertex[d]);
            }
      }
    return {lower, upper};
  }



  template <int dim>
  double
  Body<dim>::volume() const
  {
    if (shape == Shape::box)
      {
        double product = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          product *= upper_corner[d] - lower_corner[d];
        return product;
      }
    if (shape == Shape::disc)
      return numbers::PI * radius * radius;
    if (shape == Shape::sphere)
      return 4. / 3. * numbers::PI * radius * radius * radius;
    if (shape == Shape::cylinder)
      return numbers::PI * radius * radius * height;
    double twice_area = 0.;
    for (unsigned int i = 0; i < vertices.size(); ++i)
      {
        const auto &a = vertices[i], &b = vertices[(i + 1) % vertices.size()];
        twice_area += a[0] * b[1] - b[0] * a[1];
      }
    return std::abs(twice_area) / 2.;
  }



  template <int dim>
  bool
  Body<dim>::contains(const Point<dim> &x) const
  {
    if (shape == Shape::box)
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (!(x[d] > lower_corner[d] && x[d] < upper_corner[d]))
            return false;
        return true;
      }
    if (shape == Shape::disc || shape == Shape::sphere)
      return x.distance(center) < radius;
    if (shape == Shape::cylinder)
      {
        const double dx = x[0] - center[0], dy = x[1] - center[1];
        return dx * dx + dy * dy < radius * radius &&
               x[dim - 1] > center[dim - 1] &&
               x[dim - 1] < center[dim - 1] + height;
      }
    // Polygon: even-odd rule.
    bool inside = false;
    for (unsigned int i = 0, j = vertices.size() - 1; i < vertices.size();
         j = i++)
      {
        const Point<dim> &a = vertices[i], &b = vertices[j];
        if ((a[1] > x[1]) != (b[1] > x[1]) &&
            x[0] < (b[0] - a[0]) * (x[1] - a[1]) / (b[1] - a[1]) + a[0])
          inside = !inside;
      }
    return inside;
  }



  template <int dim>
  std::string
  Body<dim>::shape_description() const
  {
    std::ostringstream out;
    out << name << ": " << shape_names[static_cast<unsigned int>(shape)];
    if (shape == Shape::box)
      out << " [" << lower_corner << "] - [" << upper_corner << "]";
    else if (shape == Shape::polygon)
      out << " with " << vertices.size() << " vertices";
    else if (shape == Shape::cylinder)
      out << " base centre (" << center << ") radius " << radius << " height "
          << height;
    else
      out << " centre (" << center << ") radius " << radius;
    return out.str();
  }



  template <int dim>
  std::string
  Body<dim>::description() const
  {
    std::ostringstream out;
    out << shape_description() << ", " << points_per_direction << "^" << dim
        << " points per cell, density " << density << ", "
        << material->description();
    if (initial_stress.geostatic)
      {
        out << ", geostatic start: K0 = " << initial_stress.k0;
        if (initial_stress.surface_named)
          out << ", surface at " << initial_stress.surface_level << " m";
        else
          out << ", under the bodies above";
      }
    return out.str();
  }



  template class Body<2>;
  template class Body<3>;
} // namespace impm
