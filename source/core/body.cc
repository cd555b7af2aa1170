#include <deal.II/base/utilities.h>

#include <impm/core/body.h>
#include <impm/core/parameters.h>

#include <sstream>
#include <stdexcept>

namespace impm
{
  template <int dim>
  void
  Body<dim>::declare_parameters(ParameterHandler &prm)
  {
    for (unsigned int k = 1; k <= max_bodies; ++k)
      {
        prm.enter_subsection("Body " + std::to_string(k));
        prm.declare_entry("Shape",
                          "box",
                          Patterns::Selection("box|disc|sphere|polygon"),
                          "Region filled with material points: box (2D, 3D), "
                          "disc (2D), sphere (3D) or polygon (2D).");
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
                          "Disc or sphere: centre, in m.");
        prm.declare_entry("Radius",
                          "1",
                          Patterns::Double(0.),
                          "Disc or sphere: radius in m (> 0).");
        prm.declare_entry("Vertices",
                          "0, 0; 1, 0; 0, 1",
                          Patterns::Anything(),
                          "Polygon (2D): vertices 'x, y; x, y; ...' in order "
                          "(at least three).");
        prm.declare_entry("Points per cell direction",
                          "2",
                          Patterns::Integer(1, 10),
                          "n: each cell the body fills holds up to n^dim "
                          "regularly placed material points (1 to 10).");
        prm.declare_entry("Density",
                          "1000",
                          Patterns::Double(0.),
                          "Initial density rho_0 in kg/m^3 (>= 0).");
        prm.enter_subsection("Material");
        MaterialRegistry::declare_parameters(prm);
        prm.leave_subsection();
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  Body<dim>::parse_parameters(ParameterHandler &prm, const unsigned int number)
  {
    name = "Body " + std::to_string(number);
    prm.enter_subsection(name);
    shape = static_cast<Shape>(Parameters::selection_index(shape_names,
                                                           name + "/Shape",
                                                           prm.get("Shape")));
    if ((shape == Shape::disc || shape == Shape::polygon) && dim != 2)
      Parameters::bad_value(name + "/Shape",
                            prm.get("Shape"),
                            "in 3D only box or sphere.");
    if (shape == Shape::sphere && dim != 3)
      Parameters::bad_value(name + "/Shape",
                            "sphere",
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
    else if (shape == Shape::disc || shape == Shape::sphere)
      {
        const auto c = Parameters::get_vector(prm, name, "Center", dim);
        for (unsigned int d = 0; d < dim; ++d)
          center[d] = c[d];
        radius = prm.get_double("Radius");
        if (!(radius > 0.))
          Parameters::bad_value(name + "/Radius",
                                prm.get("Radius"),
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
      }
    points_per_direction = prm.get_integer("Points per cell direction");
    density              = prm.get_double("Density");
    prm.enter_subsection("Material");
    material = MaterialRegistry::create(prm);
    prm.leave_subsection();
    prm.leave_subsection();
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
  Body<dim>::description() const
  {
    std::ostringstream out;
    out << name << ": " << shape_names[static_cast<unsigned int>(shape)];
    if (shape == Shape::box)
      out << " [" << lower_corner << "] - [" << upper_corner << "]";
    else if (shape == Shape::polygon)
      out << " with " << vertices.size() << " vertices";
    else
      out << " centre (" << center << ") radius " << radius;
    out << ", " << points_per_direction << "^" << dim
        << " points per cell, density " << density << ", "
        << material->description();
    return out.str();
  }



  template class Body<2>;
  template class Body<3>;
} // namespace impm
