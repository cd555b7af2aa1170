#ifndef impm_core_rigid_shapes_h
#define impm_core_rigid_shapes_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <impm/core/rigid_shape.h>
#include <impm/core/triangulated_surface.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief A box between two corners (2D and 3D), with flat sides.
   *
   * With a Facing, a point is measured against the shallowest of the sides
   * whose normal opposes the face's, in front of which the face started the
   * step, and which the face overlaps; the face presses with the part of it
   * over the side (Proximity::overlap), so that contact begins and ends
   * gradually as a face slides over an edge. Defined in rigid_box.cc.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class RigidBox final : public RigidShape<dim>
  {
  public:
    using typename RigidShape<dim>::Proximity;
    using typename RigidShape<dim>::Facing;
    using typename RigidShape<dim>::Surface;

    /** @brief The box between @p lower and @p upper (each coordinate of
     *  @p upper above @p lower's). */
    RigidBox(const Point<dim> &lower, const Point<dim> &upper);

    /** @brief See RigidShape::proximity(): inside the nearest side (with a
     *  Facing: the side that pushes the face), outside the nearest point of
     *  the box, whose normal turns at edges and corners. */
    Proximity
    proximity(const Point<dim> &y, const Facing *facing) const override;

    /** @brief The box itself. */
    std::pair<Point<dim>, Point<dim>>
    bounding_box() const override;

    /** @brief The outline (2D) or the six sides (3D). */
    Surface
    surface() const override;

    /** @brief "box [lower] - [upper]". */
    std::string
    description() const override;

    /** @brief True: a face is probed at its centre. */
    bool
    exact_face_overlap() const override
    {
      return true;
    }

    /** @brief The same box as a polygon (2D) or a surface of 12 triangles
     *  (3D, described as 'turning box'). */
    std::unique_ptr<RigidShape<dim>>
    turning_form() const override;

  private:
    /** @brief The corners, vertex k having coordinate d from upper where
     *  bit d of k is set. */
    std::vector<Point<dim>>
    corners() const;

    /** The lower and upper corners. */
    Point<dim> lower, upper;
  };



  /**
   * @brief A disc (2D) or a sphere (3D): one normal, from the centre,
   * turning with the point. Defined in rigid_ball.cc.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class RigidBall final : public RigidShape<dim>
  {
  public:
    using typename RigidShape<dim>::Proximity;
    using typename RigidShape<dim>::Facing;
    using typename RigidShape<dim>::Surface;

    /** @brief The disc or sphere about @p center of radius @p radius. */
    RigidBall(const Point<dim> &center, const double radius);

    /** @brief See RigidShape::proximity() (the facing is ignored). */
    Proximity
    proximity(const Point<dim> &y, const Facing *facing) const override;

    /** @brief The centre plus and minus the radius. */
    std::pair<Point<dim>, Point<dim>>
    bounding_box() const override;

    /** @brief A polygon of 64 sides (2D) or 16 x 32 quadrilaterals (3D). */
    Surface
    surface() const override;

    /** @brief "disc centre (c) radius r" ("sphere" in 3D). */
    std::string
    description() const override;

  private:
    /** The centre. */
    Point<dim> center;
    /** The radius. */
    double radius;
  };



  /**
   * @brief A polygon (2D), given by its vertices in order (either
   * orientation). Defined in rigid_polygon.cc.
   *
   * With a Facing and inside, a point is measured below the nearest edge
   * line of those that oppose the face and in front of which the face
   * started the step (a flat surface; exact for a convex polygon).
   */
  class RigidPolygon final : public RigidShape<2>
  {
  public:
    /** @brief The polygon with @p vertices (at least three, in order). */
    explicit RigidPolygon(const std::vector<Point<2>> &vertices);

    /**
     * @brief The proximity of @p x to the polygon with @p vertices (in
     * order, either orientation), without a Facing: the nearest point of
     * the outline, the normal turning at a vertex. Also the profile of a
     * RigidCone.
     */
    static Proximity
    planar_proximity(const std::vector<Point<2>> &vertices, const Point<2> &x);

    /** @brief See RigidShape::proximity(). */
    Proximity
    proximity(const Point<2> &y, const Facing *facing) const override;

    /** @brief The box of the vertices. */
    std::pair<Point<2>, Point<2>>
    bounding_box() const override;

    /** @brief The outline. */
    Surface
    surface() const override;

    /** @brief "polygon with n vertices". */
    std::string
    description() const override;

  private:
    /** @brief Whether @p x lies inside (even-odd rule, as
     *  Body::contains()). */
    bool
    contains(const Point<2> &x) const;

    /** The vertices in order. */
    std::vector<Point<2>> vertices;
  };



  /**
   * @brief A cone on a cylindrical shaft (3D), a penetrometer: the solid
   * swept by turning its profile about the axis. Defined in
   * rigid_cone.cc.
   *
   * A point's proximity is its profile's (RigidPolygon::planar_proximity())
   * in the plane through the axis and the point, turned about the axis.
   */
  class RigidCone final : public RigidShape<3>
  {
  public:
    /** @brief Declare the cone's entries (Tip, Axis, Cone height, Cone
     *  radius, Shaft length) in the current subsection. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** @brief Read the cone's entries from the current subsection; @p name
     *  names the body in messages. */
    RigidCone(ParameterHandler &prm, const std::string &name);

    /** @brief See RigidShape::proximity() (the facing is ignored). */
    Proximity
    proximity(const Point<3> &y, const Facing *facing) const override;

    /** @brief The tip and the circles of the base and the shaft's top. */
    std::pair<Point<3>, Point<3>>
    bounding_box() const override;

    /** @brief The profile's corners turned about the axis in 32 steps. */
    Surface
    surface() const override;

    /** @brief "cone tip (t) axis (a) height h radius r shaft s". */
    std::string
    description() const override;

  private:
    /** The tip. */
    Point<3> tip;
    /** Unit vector from the tip toward the base. */
    Tensor<1, 3> axis;
    /** Radius of the base (and the shaft), height from the tip to the
     *  base and the shaft's length above the base. */
    double radius = 0., height = 0., shaft_length = 0.;
    /** The profile in the plane through the axis, as (distance from the
     *  axis, height above the tip), mirrored about the axis: a closed
     *  polygon. */
    std::vector<Point<2>> profile;
  };



  /**
   * @brief A rigid cone on its shaft in the meridian plane of an
   * axisymmetric grid (2D, x the radius): the profile of RigidCone, with
   * the same proximity (the nearest edge of the profile, the normal
   * turning with the point about a corner outside), so that an
   * axisymmetric run and a 3D one probe the same shape. The tip lies on
   * the axis (x = 0) and the axis points along +y or -y. Defined in
   * rigid_cone.cc.
   */
  class RigidConeProfile final : public RigidShape<2>
  {
  public:
    /** @brief Read the cone's entries (RigidCone::declare_parameters())
     *  from the current subsection, Tip and Axis with two components; @p
     *  name names the body in messages. */
    RigidConeProfile(ParameterHandler &prm, const std::string &name);

    /** @brief See RigidShape::proximity() (the facing is ignored). */
    Proximity
    proximity(const Point<2> &y, const Facing *facing) const override;

    /** @brief The profile's box (both sides of the axis). */
    std::pair<Point<2>, Point<2>>
    bounding_box() const override;

    /** @brief The profile on the side x >= 0. */
    Surface
    surface() const override;

    /** @brief "cone (meridian plane) tip (t) axis ... ". */
    std::string
    description() const override;

    /** @brief True. */
    bool
    needs_axisymmetry() const override
    {
      return true;
    }

  private:
    /** The tip (on the axis). */
    Point<2> tip;
    /** +1 if the axis points along +y (from the tip to the base), -1 along
     *  -y. */
    double direction = 1.;
    /** As RigidCone's. */
    double radius = 0., height = 0., shaft_length = 0.;
    /** As RigidCone's: (r, height above the tip), mirrored about the axis. */
    std::vector<Point<2>> profile;
  };



  /**
   * @brief A closed triangulated surface (3D), read from an STL file
   * (TriangulatedSurface), or a turning box's sides. Defined in
   * rigid_triangulated_surface.cc.
   */
  class RigidTriangulatedSurface final : public RigidShape<3>
  {
  public:
    /** @brief Declare the entry 'STL file' in the current subsection. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** @brief Read the surface from the file named by 'STL file' in the
     *  current subsection; @p name names the body in messages. */
    RigidTriangulatedSurface(ParameterHandler &prm, const std::string &name);

    /** @brief The surface @p mesh, described as from @p source. */
    RigidTriangulatedSurface(TriangulatedSurface &&mesh,
                             const std::string    &source);

    /** @brief See RigidShape::proximity() (the facing is ignored). */
    Proximity
    proximity(const Point<3> &y, const Facing *facing) const override;

    /** @brief The box of the vertices. */
    std::pair<Point<3>, Point<3>>
    bounding_box() const override;

    /** @brief The triangles. */
    Surface
    surface() const override;

    /** @brief "surface 'file' of n triangles". */
    std::string
    description() const override;

  private:
    /** The STL file's name (or what the surface is). */
    std::string source;
    /** The surface. */
    TriangulatedSurface mesh;
  };
} // namespace impm

#endif
