#ifndef impm_core_body_h
#define impm_core_body_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <impm/mechanics/material.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief A body: a region of the scene filled with material points, with
   * its own points per cell, density and material.
   *
   * Shapes: box (2D and 3D), disc (2D), sphere (3D), cylinder (3D, along
   * z) and polygon (2D, given
   * by its vertices in order). Points are placed at n regular positions per
   * cell and direction wherever those positions lie inside the shape.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class Body
  {
  public:
    /** Largest number of bodies a scene can name. */
    static constexpr unsigned int max_bodies = 4;

    /**
     * @brief Declare the entries of subsection "Body k" (k = 1 ... 4): shape,
     * geometry, points per cell, density and a "Material" subsection with
     * the registered material models.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief Declare the entries of a shape (Shape, Lower corner, Upper
     * corner, Center, Radius, Vertices) in the current subsection: shared by
     * the bodies and the rigid bodies.
     * @param prm The scene's parameters, in the body's subsection.
     * @param extra_shapes Further names for the Shape selection (the rigid
     * bodies' "|cone"), parsed by the caller.
     */
    static void
    declare_shape_parameters(ParameterHandler  &prm,
                             const std::string &extra_shapes = "");

    /**
     * @brief Read the entries of declare_shape_parameters() from the current
     * subsection (messages name the entries after #name) and check them.
     */
    void
    parse_shape(ParameterHandler &prm);

    /**
     * @brief Read body @p number (1-based) from subsection "Body number".
     */
    void
    parse_parameters(ParameterHandler &prm, const unsigned int number);

    /**
     * @brief Whether @p x lies inside the body's shape.
     */
    bool
    contains(const Point<dim> &x) const;

    /**
     * @brief The smallest box holding the body's shape: its lower and upper
     * corner.
     */
    std::pair<Point<dim>, Point<dim>>
    bounding_box() const;

    /**
     * @brief The volume (area in 2D) of the body's shape.
     */
    double
    volume() const;

    /** @brief A piece of a body's true boundary. */
    struct BoundaryPiece
    {
      /** Its midpoint on the boundary. */
      Point<dim> midpoint;
      /** Its length (2D) or area (3D). */
      double size;
      /** The outward unit normal at the midpoint. */
      Tensor<1, dim> normal;
    };

    /**
     * @brief The part of the boundary whose outward normal points along @p
     * sign times the axis @p axis, in pieces: in 2D a box's side, half a
     * disc, the polygon's edges facing that way, cut where they cross the
     * lattice lines @f$x_j = o_j + m\,s_j@f$ of the other axis j (@p origin
     * o, @p spacing s); in 3D the half sphere in zones of equal height
     * along the axis (of about @p spacing), each cut into equal sectors,
     * and a cylinder's end or half its side (add_cylinder_pieces()).
     * Their sizes add up to the length or area of that part of the
     * boundary, to round-off. Empty for a box in 3D (its lattice faces are
     * exact).
     */
    std::vector<BoundaryPiece>
    boundary_pieces(const unsigned int    axis,
                    const double          sign,
                    const Point<dim>     &origin,
                    const Tensor<1, dim> &spacing) const;

    /**
     * @brief The whole boundary in pieces, each part once (as
     * boundary_pieces(); a polygon's edges cut across their longer extent,
     * a sphere in zones along z, a cylinder's ends and side): for loads on
     * the sides a region selects.
     * Empty for a box in 3D.
     */
    std::vector<BoundaryPiece>
    boundary_partition(const Point<dim>     &origin,
                       const Tensor<1, dim> &spacing) const;

    /**
     * @brief The name, shape and size: "Body 1: box [0 0] - [1 1]".
     */
    std::string
    shape_description() const;

    /**
     * @brief A one-line description for the start-up report and summary.
     */
    std::string
    description() const;

    /** Name used in messages ("Body 1", ...). */
    std::string name;
    /** @brief The shapes a body can have. */
    enum class Shape
    {
      /** A box between two corners (2D and 3D). */
      box,
      /** A disc (2D). */
      disc,
      /** A sphere (3D). */
      sphere,
      /** A polygon (2D). */
      polygon,
      /** A circular cylinder along z (3D). */
      cylinder
    };

    /** The scene's names of the shapes, in enum order. */
    static constexpr std::array<const char *, 5> shape_names = {
      {"box", "disc", "sphere", "polygon", "cylinder"}};

    /** The body's shape. */
    Shape shape = Shape::box;
    /** Box: the lower corner. */
    Point<dim> lower_corner;
    /** Box: the upper corner. */
    Point<dim> upper_corner;
    /** Disc or sphere centre; a cylinder's base centre. */
    Point<dim> center;
    /** Disc, sphere or cylinder radius. */
    double radius = 0.;
    /** Cylinder height (along z, up from its base centre). */
    double height = 0.;
    /** Polygon vertices (2D). */
    std::vector<Point<dim>> vertices;
    /** Points per cell and direction. */
    unsigned int points_per_direction = 2;
    /** Initial density. */
    double density = 0.;
    /** The body's constitutive model. */
    std::shared_ptr<Material> material;

    /** @brief The stress a body starts from. */
    struct InitialStress
    {
      /** Geostatic (true) or zero (false). */
      bool geostatic = false;
      /** Ratio K0 of horizontal to vertical stress. */
      double k0 = 0.5;
      /** Whether the scene names a horizontal free surface ("Surface
       *  level"); if not, a point's overburden is the material above it. */
      bool surface_named = false;
      /** The named surface's elevation along the last axis. */
      double surface_level = 0.;
    };
    /** The initial stress. */
    InitialStress initial_stress;

    /**
     * @brief The length of the vertical line (along the last axis) above
     * @p x that lies inside the body's shape: for a point inside a box, the
     * height of the box above it; for a polygon, the sum of the line's
     * pieces inside it above @p x (even-odd rule, as contains()).
     */
    double
    height_inside_above(const Point<dim> &x) const;

    /**
     * @brief The geostatic Kirchhoff stress at @p x under the acceleration
     * of gravity @p g (along the last axis): vertical @f$-g\,w@f$ with the
     * overburden w (mass per unit area above @p x), horizontal (and, in
     * plane strain, out of plane) K0 times that. Without a named surface,
     * w is the sum over @p bodies (this one among them) of each body's
     * density times height_inside_above(): layers, slopes and a body
     * resting on another start from the weight they carry. With a named
     * surface, w is this body's density times the depth below it (zero
     * above it).
     */
    SymmetricTensor<2, 3>
    geostatic_stress(const Point<dim>             &x,
                     const double                  g,
                     const std::vector<Body<dim>> &bodies) const;

  private:
    /** @brief An edge of a polygon: start, tangent (to the next vertex),
     *  outward unit normal. */
    struct PolygonEdge
    {
      Point<dim>     start;
      Tensor<1, dim> tangent;
      Tensor<1, dim> normal;
    };

    /** @brief The polygon's edges (2D). */
    std::vector<PolygonEdge>
    polygon_edges() const;

    /** @brief Add an edge's pieces, cut at the lattice lines of axis @p j. */
    void
    add_edge_pieces(const PolygonEdge          &edge,
                    const unsigned int          j,
                    const Point<dim>           &origin,
                    const Tensor<1, dim>       &spacing,
                    std::vector<BoundaryPiece> &pieces) const;

    /**
     * @brief Add the sphere's zones between the planes u = @p low and u =
     * @p high normal to @p axis, each cut into sectors (3D).
     */
    void
    add_sphere_zones(const unsigned int          axis,
                     const double                low,
                     const double                high,
                     const Tensor<1, dim>       &spacing,
                     std::vector<BoundaryPiece> &pieces) const;

    /**
     * @brief Add the cylinder's pieces facing @p sign along @p axis (3D):
     * for z its flat end cut at the lattice lines in x and y (each lattice
     * cell's part of the disc, at the cell's centre); for x or y the half
     * of its side, cut at the lattice lines in z and into an even number
     * of sectors (area R dphi dz), so that the plane through the axis
     * across the half (a quarter model's symmetry plane) falls between
     * pieces. Every piece's area is exact.
     */
    void
    add_cylinder_pieces(const unsigned int          axis,
                        const double                sign,
                        const Point<dim>           &origin,
                        const Tensor<1, dim>       &spacing,
                        std::vector<BoundaryPiece> &pieces) const;

    /**
     * @brief Refuse a polygon whose edges cross or touch other than at
     * shared vertices, or that has no area (@p value: the entry, for the
     * message).
     */
    void
    check_polygon(const std::string &value) const;
  };
} // namespace impm

#endif
