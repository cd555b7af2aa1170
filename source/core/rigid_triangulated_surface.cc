// A rigid body given by a closed triangulated surface
// (RigidTriangulatedSurface, 3D): an STL file or a turning box's sides. The
// geometry is TriangulatedSurface's.
#include <impm/core/parameters.h>
#include <impm/core/rigid_shapes.h>

#include <sstream>
#include <stdexcept>

namespace impm
{
  namespace
  {
    /** The surface in @p file_name; a fault is an error naming the entry
     *  'STL file' of @p name. */
    TriangulatedSurface
    read_surface(const std::string &file_name, const std::string &name)
    {
      try
        {
          return TriangulatedSurface(file_name);
        }
      catch (const std::runtime_error &error)
        {
          Parameters::bad_value(name + "/STL file",
                                file_name,
                                std::string(error.what()) + ".");
        }
    }
  } // namespace



  void
  RigidTriangulatedSurface::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("STL file",
                      "",
                      Patterns::Anything(),
                      "stl (3D): a closed, consistently oriented "
                      "triangulated surface, binary or ASCII STL, "
                      "coordinates in m; a relative path is relative to "
                      "the scene file's directory.");
  }



  RigidTriangulatedSurface::RigidTriangulatedSurface(ParameterHandler  &prm,
                                                     const std::string &name)
    : source(prm.get("STL file"))
    , mesh(read_surface(source, name))
  {}



  RigidTriangulatedSurface::RigidTriangulatedSurface(TriangulatedSurface &&mesh,
                                                     const std::string &source)
    : source(source)
    , mesh(std::move(mesh))
  {}



  RigidTriangulatedSurface::Proximity
  RigidTriangulatedSurface::proximity(const Point<3> &y, const Facing *) const
  {
    Proximity  result;
    const auto nearest       = mesh.proximity(y);
    result.gap               = nearest.gap;
    result.normal            = nearest.normal;
    result.normal_derivative = nearest.normal_derivative;
    return result;
  }



  std::pair<Point<3>, Point<3>>
  RigidTriangulatedSurface::bounding_box() const
  {
    return mesh.bounding_box();
  }



  RigidTriangulatedSurface::Surface
  RigidTriangulatedSurface::surface() const
  {
    Surface result;
    result.vertices = mesh.get_vertices();
    for (const auto &triangle : mesh.get_triangles())
      result.faces.push_back({triangle[0], triangle[1], triangle[2]});
    return result;
  }



  std::string
  RigidTriangulatedSurface::description() const
  {
    std::ostringstream out;
    out << "surface '" << source << "' of " << mesh.get_triangles().size()
        << " triangles";
    return out.str();
  }
} // namespace impm
