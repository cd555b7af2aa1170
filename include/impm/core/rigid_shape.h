#ifndef impm_core_rigid_shape_h
#define impm_core_rigid_shape_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The shape of a rigid body (RigidBody), in the body's own frame
   * (before its displacement and rotation): what the contact asks of the
   * geometry, the same for every shape.
   *
   * A shape answers where a point is relative to its surface (the signed
   * distance, negative inside, the outward normal of the nearest surface
   * point and the normal's derivative, which the consistent tangent of the
   * contact needs), the smallest box holding it, its surface as polygons
   * for output and a line describing it. RigidBody owns one, made once from
   * its parameters by create(), and moves and turns it.
   *
   * The shapes are in rigid_shapes.h, one class each: RigidBox,
   * RigidBall (disc or sphere), RigidPolygon, RigidCone (a cone on a
   * shaft) and RigidTriangulatedSurface (an STL file). A new shape is a
   * class derived from this one plus its name and creation in
   * declare_parameters() and create() (rigid_shape.cc).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class RigidShape
  {
  public:
    /**
     * @brief Where a point is relative to the surface of the shape.
     */
    struct Proximity
    {
      /** Signed distance from the surface, negative inside. */
      double gap = std::numeric_limits<double>::max();
      /** Outward unit normal of the nearest surface point. */
      Tensor<1, dim> normal;
      /** The derivative of the normal with respect to the point
       *  (symmetric; zero on flat parts, (I - n n)/r on a disc or
       *  sphere of radius r). */
      Tensor<2, dim> normal_derivative;
      /** The part of the face (Facing) that presses on the surface, in
       *  [0, 1]: 1 but where a face overlaps a box's edge. */
      double overlap = 1.;
      /** Its derivative with respect to the point. */
      Tensor<1, dim> overlap_gradient;
      /** Which piece of the piecewise smooth contact the point is on: the
       *  side pushing it and, on a box, which of the face's ends lie beyond
       *  the side's edges (where the overlap's slope changes). A change
       *  between two evaluations is a change of contact state, like
       *  entering or leaving contact. */
      unsigned int piece = 0;
    };

    /**
     * @brief A material point's domain face, for proximity(): which sides
     * of a box or polygon may push it.
     */
    struct Facing
    {
      /** The face's outward normal. */
      Tensor<1, dim> normal;
      /** Its centre at the start of the step, in the body's frame (minus
       *  the body's displacement at the start of the step). */
      Point<dim> start;
      /** How far inside a side's plane the start may lie (the penalty's
       *  penetration of the step before). */
      double tolerance = 0.;
      /** How far inside a side's plane the start may lie if it lies over
       *  the side (within its extent along it): the penetration of an
       *  explicit step's impact, deeper than the penalty's. */
      double deep_tolerance = 0.;
      /** The domain's half-lengths (those along the face count). */
      Tensor<1, dim> half_length;
    };

    /** @brief A shape's surface as polygons, for ParaView. */
    struct Surface
    {
      /** The vertices. */
      std::vector<Point<dim>> vertices;
      /** Each face: its vertices' indices in order (in 2D one polygon,
       *  the body's outline; in 3D quadrilaterals or triangles). */
      std::vector<std::vector<unsigned int>> faces;
    };

    /** @brief Destructor. */
    virtual ~RigidShape() = default;

    /**
     * @brief Declare the entries of the shapes in the current subsection:
     * 'Shape' (box, disc, sphere, polygon, cone, stl), a Body's entries
     * for the first four, then each other shape's own.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief The shape named by 'Shape' in the current subsection, read
     * from its entries: the one place that maps a shape's name to its
     * class. @p name names the body in messages ("Rigid body 1").
     */
    static std::unique_ptr<RigidShape<dim>>
    create(ParameterHandler &prm, const std::string &name);

    /**
     * @brief The proximity of @p y (in the shape's frame). Exact inside the
     * shape (where the contact acts); outside only the gap's sign and size
     * are used. @p facing (a material point's domain face, or null) may
     * choose the side that pushes the face (RigidBody::proximity()); shapes
     * with one normal ignore it. Called for every probe of the contact:
     * it must not allocate.
     */
    virtual Proximity
    proximity(const Point<dim> &y, const Facing *facing) const = 0;

    /** @brief The smallest box holding the shape: its lower and upper
     *  corners. */
    virtual std::pair<Point<dim>, Point<dim>>
    bounding_box() const = 0;

    /** @brief The shape's surface as polygons (curved surfaces as many
     *  flat faces), for output. */
    virtual Surface
    surface() const = 0;

    /** @brief The shape and its size for the start-up report, after the
     *  body's name ("box [0 0] - [1 1]"). */
    virtual std::string
    description() const = 0;

    /**
     * @brief Whether proximity() with a Facing gives the exact part of the
     * face that presses (Proximity::overlap), so that the face's centre
     * alone is probed; otherwise the contact probes Gauss points on the
     * face. False unless overridden (true for a box).
     */
    virtual bool
    exact_face_overlap() const
    {
      return false;
    }

    /**
     * @brief Whether the shape is the meridian plane of a body of
     * revolution, which only an axisymmetric grid makes (false unless
     * overridden: a 2D cone).
     */
    virtual bool
    needs_axisymmetry() const
    {
      return false;
    }

    /**
     * @brief The shape to probe instead when the body turns, or null for
     * this one (unless overridden): a box's exact face overlap holds for
     * faces parallel to its sides only, so a turning box is probed as a
     * polygon (2D) or a surface of triangles (3D).
     */
    virtual std::unique_ptr<RigidShape<dim>>
    turning_form() const
    {
      return nullptr;
    }
  };
} // namespace impm

#endif
