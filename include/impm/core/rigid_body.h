#ifndef impm_core_rigid_body_h
#define impm_core_rigid_body_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <impm/core/rigid_shape.h>
#include <impm/core/triangulated_surface.h> // still provides it

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief A rigid body of a scene: a shape (box, disc, sphere or polygon,
   * as a Body's, or in 3D a cone on a cylindrical shaft, a penetrometer,
   * or a closed triangulated surface read from an STL file)
   * that moves through the grid by a prescribed displacement and
   * optionally a rotation about a centre, both ramped with the load
   * factor (or, on its force-driven components, pushed by a force, its
   * displacement there an unknown of RigidContact), and touches the
   * material points with a penalty contact and Coulomb friction
   * (RigidContact).
   *
   * It owns its shape (a RigidShape, made once from the parameters by
   * RigidShape::create()) and moves and turns it: the signed distance of a
   * point from its surface (negative inside), the outward normal of the
   * nearest surface point and the derivative of that normal, which the
   * consistent tangent of the contact needs, are the shape's at the point
   * mapped to the body's frame.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class RigidBody
  {
  public:
    /** Largest number of rigid bodies a scene can name. */
    static constexpr unsigned int max_rigid_bodies = 4;

    /** @brief How the body's surface resists sliding. */
    enum class Friction
    {
      /** No tangential force. */
      frictionless,
      /** Coulomb: stick while the tangential traction is below the
       *  friction coefficient times the pressure, slip at it. */
      coulomb,
      /** No slip at any tangential traction. */
      rough
    };

    /** The scene's names of the friction laws, in enum order. */
    static constexpr std::array<const char *, 3> friction_names = {
      {"frictionless", "coulomb", "rough"}};

    /**
     * @brief Declare the entries of subsections "Rigid body k" (k = 1 ...
     * 4): the shape, the displacement, the friction and the penalty.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief Read rigid body @p number (1-based) from subsection "Rigid
     * body number".
     */
    void
    parse_parameters(ParameterHandler &prm, const unsigned int number);

    /** @brief Where a point is relative to the surface of the body
     *  (RigidShape::Proximity). */
    using Proximity = typename RigidShape<dim>::Proximity;

    /** @brief A material point's domain face, for proximity(): which sides
     *  of a box or polygon may push it (RigidShape::Facing). */
    using Facing = typename RigidShape<dim>::Facing;

    /** @brief The body's surface as polygons, for ParaView
     *  (RigidShape::Surface). */
    using Surface = typename RigidShape<dim>::Surface;

    /**
     * @brief The proximity of @p x to the body displaced by @p
     * displacement. Exact inside the body (where the contact acts); outside
     * only the gap's sign and size are used.
     *
     * With @p facing (a material point's domain face), a point is measured
     * against the shallowest of the flat sides of a box or polygon whose
     * normal opposes the face's and in front of which the face started the
     * step (none: not in contact). So a face under a box's corner is pushed
     * back through the side it came through, not through whichever side is
     * nearest (which flips between Newton iterates near the corner's
     * diagonal), and a face the body has passed over sideways is not pushed
     * through the far side. On a box, a face that overlaps a side's edge
     * presses with the part of it that overlaps (Proximity::overlap), so
     * that contact begins and ends gradually as a face slides over an edge.
     * Discs and spheres have one normal and ignore it.
     */
    Proximity
    proximity(const Point<dim>     &x,
              const Tensor<1, dim> &displacement,
              const Facing         *facing = nullptr) const
    {
      // Inline: one call (the shape's) per probe.
      return shape->proximity(x - displacement, facing);
    }

    /**
     * @brief The proximity of @p x to the body displaced by @p displacement
     * and turned by @p rotation about its displaced 'Rotation centre': the
     * proximity of the point x maps to in the body's frame, c + R^T (x - c
     * - d), turned back (the normal R n, its derivative R H R^T). @p
     * facing is in the body's frame (its normal R^T n_f, its start mapped
     * with the start's pose).
     */
    Proximity
    proximity(const Point<dim>     &x,
              const Tensor<1, dim> &displacement,
              const Tensor<2, dim> &rotation,
              const Facing         *facing) const;

    /** @brief Whether the body turns ('Rotation' is not zero). */
    bool
    rotates() const
    {
      return rotation_angle != 0.;
    }

    /**
     * @brief The body's rotation at load factor @p load_factor: the angle
     * 'Rotation' times the load factor, about z in 2D (counter-clockwise)
     * or about 'Rotation axis' in 3D (right-handed).
     */
    Tensor<2, dim>
    rotation_at(const double load_factor) const;

    /**
     * @brief Where @p x lies in the body's frame when the body is displaced
     * by @p displacement and turned by @p rotation: c + R^T (x - c - d).
     */
    Point<dim>
    to_body_frame(const Point<dim>     &x,
                  const Tensor<1, dim> &displacement,
                  const Tensor<2, dim> &rotation) const
    {
      return rotation_centre +
             transpose(rotation) * (x - rotation_centre - displacement);
    }

    /**
     * @brief The body's displacement at load factor @p load_factor (on
     * force-driven components zero: there it is an unknown).
     */
    Tensor<1, dim>
    displacement_at(const double load_factor) const
    {
      return load_factor * displacement;
    }

    /** @brief Whether component @p d is pushed by the force. */
    bool
    is_force_driven(const unsigned int d) const
    {
      return std::find(force_components.begin(), force_components.end(), d) !=
             force_components.end();
    }

    /**
     * @brief The smallest box holding the body displaced by @p displacement.
     */
    std::pair<Point<dim>, Point<dim>>
    bounding_box(const Tensor<1, dim> &displacement) const;

    /**
     * @brief A box holding the body displaced by @p displacement and turned
     * by its rotation at @p load_factor (the turned corners of its box).
     */
    std::pair<Point<dim>, Point<dim>>
    bounding_box(const Tensor<1, dim> &displacement,
                 const double          load_factor) const;

    /**
     * @brief The surface of the body displaced by @p displacement: a box's
     * outline or faces, a polygon, and discs and spheres as polygons of 64
     * sides or 16 x 32 quadrilaterals.
     */
    Surface
    surface(const Tensor<1, dim> &displacement) const;

    /**
     * @brief The surface of the body displaced by @p displacement and
     * turned by its rotation at @p load_factor.
     */
    Surface
    surface(const Tensor<1, dim> &displacement, const double load_factor) const;

    /**
     * @brief The Gauss points per direction along a face of a point's
     * domain at which the body is probed: 1 for a box (the face's centre,
     * with the face's exact overlap of the side), 'Face quadrature points'
     * for the other shapes.
     */
    unsigned int
    face_points() const
    {
      return shape->exact_face_overlap() ? 1 : face_quadrature_points;
    }

    /** @brief A one-line description for the start-up report. */
    std::string
    description() const;

    /** @brief The body's shape, in its own frame. */
    const RigidShape<dim> &
    get_shape() const
    {
      return *shape;
    }

    /** Name in messages and columns ("Rigid body 1", ...). */
    std::string name;
    /** Displacement at load factor 1. */
    Tensor<1, dim> displacement;
    /** The components in which the body is pushed by @p force (its
     *  displacement there an unknown), in increasing order. */
    std::vector<unsigned int> force_components;
    /** Force on the body at load factor 1 (zero but on
     *  force_components). */
    Tensor<1, dim> force;
    /** The angle turned at load factor 1, in radians (0: none). */
    double rotation_angle = 0.;
    /** The axis of the rotation (3D; unit length). */
    Tensor<1, dim> rotation_axis;
    /** The point the body turns about, before its displacement. */
    Point<dim> rotation_centre;
    /** The friction law. */
    Friction friction = Friction::frictionless;
    /** Coulomb friction coefficient. */
    double friction_coefficient = 0.;
    /** Penalty factor: the normal and tangential stiffness per area is
     *  this times Young's modulus of the touching point's material over
     *  the smallest cell size. */
    double penalty_factor = 100.;
    /** Tangential penalty factor: the stick stiffness per area is this
     *  times E / h. */
    double tangential_penalty_factor = 10.;
    /** Gauss points per direction on a face (not for boxes). */
    unsigned int face_quadrature_points = 3;

  private:
    /** The shape, made from the parameters by RigidShape::create() (for a
     *  turning box, its RigidShape::turning_form()). */
    std::unique_ptr<RigidShape<dim>> shape;

    /** @brief Read 'Force-driven components' and 'Force' (after
     *  'Displacement'). */
    void
    parse_force(ParameterHandler &prm);

    /** @brief Read 'Rotation', 'Rotation axis' and 'Rotation centre'
     *  (after the shape); a turning shape is probed in its
     *  RigidShape::turning_form() if it has one (a box: a polygon (2D) or a
     *  surface of 12 triangles (3D), whose faces are probed at Gauss
     *  points). */
    void
    parse_rotation(ParameterHandler &prm);
  };
} // namespace impm

#endif
