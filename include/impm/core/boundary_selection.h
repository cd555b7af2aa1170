#ifndef impm_core_boundary_selection_h
#define impm_core_boundary_selection_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <impm/basis/basis_functions.h>
#include <impm/core/body.h>
#include <impm/core/effects.h>

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief A part of a body's boundary chosen in a scene (a side by its
   * outward normal, or every side inside a region) and the material points
   * that carry it: each boundary point carries the part of the true
   * boundary nearest to it, on the faces of its domain, so that the areas
   * add up to the true length or area of that part. What a traction loads
   * and what springs support.
   *
   * A side, "x+", is every part of the boundary whose outward normal has a
   * positive x component (a polygon's slanted edges among them, a disc's
   * or sphere's half); likewise x-, y-, y+, z-, z+. A region clips a side
   * in every direction: in 2D each piece of it to its part inside the
   * region, so that the length loaded is the side's length inside the
   * region (Cook's membrane's x+ from y = 43: the right edge and the
   * slanted lower edge above y = 43); with `Boundary = region`, and in 3D,
   * a piece (the boundary cut at the points' lattice lines) is in when its
   * midpoint is.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class BoundarySelection
  {
  public:
    /**
     * @brief Declare `Body`, `Boundary`, `Region lower corner` and `Region
     * upper corner` in the current subsection.
     * @param prm The scene's parameters, in the subsection of the effect or
     *   coupling that selects the boundary.
     * @param verb What happens to the boundary ("loaded", "supported").
     */
    static void
    declare_parameters(ParameterHandler &prm, const std::string &verb);

    /**
     * @brief Read the entries of declare_parameters() from the current
     * subsection, @p section (its name, for messages).
     */
    BoundarySelection(ParameterHandler &prm, const std::string &section);

    /**
     * @brief Find the boundary points and their areas. Every process keeps
     * every boundary point (points move between processes). Collective.
     * @param points This process's points.
     * @param bodies The scene's bodies.
     * @param grid The background grid.
     * @param communicator The processes of the run.
     */
    void
    select(const std::vector<MaterialPointInfo<dim>> &points,
           const std::vector<Body<dim>>              &bodies,
           const CartesianGrid<dim>                  &grid,
           const MPI_Comm                             communicator);

    /** @brief Per boundary point (by id), the area it carries on each face
     *  of its domain (by face number, 2 axis + (side > 0)). */
    const std::unordered_map<std::uint64_t, std::array<double, 2 * dim>> &
    areas() const
    {
      point_areas_are_selected();
      return point_areas;
    }

    /** @brief The number of boundary points. */
    unsigned int
    n_points() const
    {
      return point_areas.size();
    }

    /** @brief The sum of the areas. */
    double
    total_area() const
    {
      return area_sum;
    }

    /** @brief Whether the part is every side inside a region (else one
     *  side, face()). */
    bool
    is_region() const
    {
      return by_region;
    }

    /** @brief The side's face number (2 axis + (side > 0)), if not
     *  is_region(). */
    unsigned int
    face() const
    {
      return boundary;
    }

    /** @brief The part in words: "the y+ side of Body 1", "the boundary in
     *  the region of Body 1". */
    std::string
    description() const;

  private:
    /** The section's name, for messages. */
    const std::string section;
    /** The body (0-based). */
    const unsigned int body;
    /** Boundary = region: every side inside the region. */
    const bool         by_region;
    const unsigned int boundary;
    Point<dim>         region_lower;
    Point<dim>         region_upper;
    bool               has_region = false;
    std::unordered_map<std::uint64_t, std::array<double, 2 * dim>> point_areas;
    double area_sum = 0.;
    bool   selected = false;

    /** Throws if select() has not been called. */
    void
    point_areas_are_selected() const;

    /** Whether @p x lies in the region (true without one). */
    bool
    in_region(const Point<dim> &x) const;

    /**
     * Give each of the body's boundary @p pieces that lies in the grid (a
     * body may cross a symmetry plane) and in the region to the nearest
     * of the boundary points @p candidates (id and initial position, by
     * id), on the face of its domain that the piece faces (the side's, or
     * with Boundary = region the one its normal points through most), in
     * axisymmetry as the ring it sweeps.
     */
    void
    add_piece_areas(
      std::vector<typename Body<dim>::BoundaryPiece>           pieces,
      const std::vector<std::pair<std::uint64_t, Point<dim>>> &candidates,
      const CartesianGrid<dim>                                &grid);
  };
} // namespace impm

#endif
