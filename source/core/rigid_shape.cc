// The shapes of the rigid bodies by name: the one place that maps the entry
// 'Shape' of a "Rigid body k" subsection to a class of rigid_shapes.h
// (declare_parameters() names them and declares their entries, create()
// makes one). Each shape's geometry is in its own file.
#include <impm/base/errors.h>
#include <impm/core/body.h>
#include <impm/core/parameters.h>
#include <impm/core/rigid_shapes.h>

#include <stdexcept>

namespace impm
{
  template <int dim>
  void
  RigidShape<dim>::declare_parameters(ParameterHandler &prm)
  {
    // A Body's shapes (box, disc, sphere, polygon) and their entries, then
    // the shapes of rigid bodies alone.
    Body<dim>::declare_shape_parameters(prm, "|cone|stl");
    RigidTriangulatedSurface::declare_parameters(prm);
    RigidCone::declare_parameters(prm);
  }



  template <int dim>
  std::unique_ptr<RigidShape<dim>>
  RigidShape<dim>::create(ParameterHandler &prm, const std::string &name)
  {
    const std::string shape   = prm.get("Shape");
    const bool        is_cone = shape == "cone";
    const bool        stl     = shape == "stl";
    if (stl && dim != 3)
      Parameters::bad_value(name + "/Shape",
                            shape,
                            "an STL surface is 3D (in 2D, a polygon).");
    if constexpr (dim == 2)
      if (is_cone)
        return std::make_unique<RigidConeProfile>(prm, name);
    if constexpr (dim == 3)
      {
        if (is_cone)
          return std::make_unique<RigidCone>(prm, name);
        if (stl)
          return std::make_unique<RigidTriangulatedSurface>(prm, name);
      }
    // A Body's shapes, read (and checked) as a Body's.
    Body<dim> outline;
    outline.name = name;
    outline.parse_shape(prm);
    using Shape = typename Body<dim>::Shape;
    switch (outline.shape)
      {
        case Shape::box:
          return std::make_unique<RigidBox<dim>>(outline.lower_corner,
                                                 outline.upper_corner);
        case Shape::disc:
        case Shape::sphere:
          return std::make_unique<RigidBall<dim>>(outline.center,
                                                  outline.radius);
        case Shape::polygon:
          if constexpr (dim == 2)
            return std::make_unique<RigidPolygon>(outline.vertices);
          break;
        case Shape::cylinder:
          throw InputError(name + "/Shape = cylinder: a shape of material "
                                  "bodies only; a rigid cylinder is an 'stl' "
                                  "surface, or a 'cone' with its shaft.");
      }
    throw std::logic_error(name + ": no rigid shape '" + shape + "' in " +
                           std::to_string(dim) + "D.");
  }



  template class RigidShape<2>;
  template class RigidShape<3>;
} // namespace impm
