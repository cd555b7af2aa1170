#ifndef impm_basis_basis_functions_h
#define impm_basis_basis_functions_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <impm/basis/basis_1d.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The weighting between material points and grid nodes.
   */
  enum class BasisType
  {
    /** Standard MPM: the Q1 shape function evaluated at the point. */
    standard_mpm,
    /** GIMP: the Q1 shape function averaged over the point's domain. */
    gimp
  };

  /**
   * @brief Convert a scene's name of a basis ("standard MPM" or "GIMP").
   *
   * @param name The name as given in the scene.
   * @return The basis type.
   */
  BasisType
  basis_type_from_string(const std::string &name);

  /**
   * @brief The scene's name of a basis ("standard MPM" or "GIMP").
   */
  std::string
  basis_name(const BasisType basis);


  /**
   * @brief Geometry of the Cartesian background grid: origin, cell size and
   * cell counts, and the map between nodes and their integer coordinates.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  struct CartesianGrid
  {
    /** Lower corner of the grid. */
    Point<dim> lower;
    /** Upper corner of the grid. */
    Point<dim> upper;
    /** Number of cells in each direction. */
    std::array<unsigned int, dim> n_cells;
    /** Cell size in each direction. */
    Tensor<1, dim> cell_size;
    /**
     * Whether the grid is the meridian plane of a solid of revolution
     * (2D only): the first coordinate is the radius r, the second the axis
     * z, and each area or length of the plane stands for the ring it
     * sweeps about the axis.
     */
    bool axisymmetric = false;

    /**
     * @brief The length of the circle that a point at @p x sweeps about the
     * axis, @f$2\pi r@f$, in axisymmetry; 1 otherwise (plane strain counts
     * per unit thickness, 3D needs no factor). A volume or mass of the
     * plane times this is that of the ring; so is an area, with the
     * radius of its centre (exact for a straight side).
     */
    double
    ring_length(const Point<dim> &x) const
    {
      return axisymmetric ? 2. * numbers::PI * x[0] : 1.;
    }

    /**
     * @brief Set up from corners and cell counts.
     */
    void
    initialize(const Point<dim>                    &lower_corner,
               const Point<dim>                    &upper_corner,
               const std::array<unsigned int, dim> &cells)
    {
      lower   = lower_corner;
      upper   = upper_corner;
      n_cells = cells;
      for (unsigned int d = 0; d < dim; ++d)
        cell_size[d] = (upper[d] - lower[d]) / n_cells[d];
    }

    /**
     * @brief Number of nodes in direction @p d.
     */
    unsigned int
    n_nodes(const unsigned int d) const
    {
      return n_cells[d] + 1;
    }

    /**
     * @brief Linear index of the node with integer coordinates @p ijk.
     */
    std::uint64_t
    node_index(const std::array<unsigned int, dim> &ijk) const
    {
      std::uint64_t index = 0;
      for (int d = dim - 1; d >= 0; --d)
        index = index * n_nodes(d) + ijk[d];
      return index;
    }

    /**
     * @brief Integer coordinates of the node at (or nearest to) @p x.
     */
    std::array<unsigned int, dim>
    nearest_node(const Point<dim> &x) const
    {
      std::array<unsigned int, dim> ijk;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const long i = std::lround((x[d] - lower[d]) / cell_size[d]);
          ijk[d]       = static_cast<unsigned int>(
            std::max(0L, std::min<long>(i, n_cells[d])));
        }
      return ijk;
    }

    /**
     * @brief Position of the node with linear index @p index
     * (node_index()).
     */
    Point<dim>
    node_position(std::uint64_t index) const
    {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        {
          x[d] = node_coordinate(d, index % n_nodes(d));
          index /= n_nodes(d);
        }
      return x;
    }

    /**
     * @brief Position of node @p i in direction @p d.
     */
    double
    node_coordinate(const unsigned int d, const long i) const
    {
      return lower[d] + i * cell_size[d];
    }

    /**
     * @brief Whether @p x lies inside the grid (boundary included).
     */
    bool
    contains(const Point<dim> &x) const
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (!(x[d] >= lower[d] && x[d] <= upper[d]))
          return false;
      return true;
    }
  };

  /**
   * @brief The nodes a material point couples to, with weights and gradients.
   *
   * Filled once per load step by BasisEvaluator::evaluate() and kept fixed
   * through that step's Newton iterations.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  struct PointSupport
  {
    /** Largest number of nodes one point can couple to (3 per direction). */
    static constexpr unsigned int max_nodes =
      dim == 1 ? 3 : (dim == 2 ? 9 : 27);

    /** Number of nodes in use. */
    unsigned int n_nodes = 0;
    /** Linear node indices (CartesianGrid::node_index). */
    std::array<std::uint64_t, max_nodes> nodes;
    /** Weights @f$S_{vp}@f$. */
    std::array<double, max_nodes> weights;
    /** Gradients @f$\partial S_{vp}/\partial \tilde x@f$. */
    std::array<Tensor<1, dim>, max_nodes> gradients;
    /** Axisymmetry only: the hoop weights, the averages of @f$N_v/r@f$
     *  over the point's ring (standard MPM: @f$N_v(x_p)/r_p@f$), which
     *  give the hoop strain @f$\sum_v \bar N_{\theta,v} u_{v,r}@f$ and the
     *  hoop force. */
    std::array<double, max_nodes> hoop_weights;
    /** Axisymmetric GIMP only: the point's radius less the centroid of
     *  its ring's volume, @f$r_p - \sum_v S_{vp} r_v@f$. The radius-weighted
     *  weights interpolate a field to that centroid; a point moves by the
     *  displacement at its own radius, the interpolated one plus this
     *  offset times the radial gradient (exact for linear fields). Zero
     *  otherwise. */
    double radial_offset = 0.;
  };

  /**
   * @brief Evaluates standard-MPM or GIMP weights and gradients of a point.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class BasisEvaluator
  {
  public:
    /**
     * @brief Constructor.
     * @param grid The background grid.
     * @param type Standard MPM or GIMP.
     */
    BasisEvaluator(const CartesianGrid<dim> &grid, const BasisType type)
      : grid(grid)
      , type(type)
    {}

    /**
     * @brief Weights and gradients of all nodes with a non-zero weight.
     *
     * @param position The point's start-of-step position.
     * @param half_length The point's GIMP domain half-lengths (ignored by
     *   standard MPM). Each must not exceed half the cell size, so that a
     *   point never couples to more than three nodes per direction.
     * @param[out] support The nodes, weights and gradients.
     */
    void
    evaluate(const Point<dim>     &position,
             const Tensor<1, dim> &half_length,
             PointSupport<dim>    &support) const
    {
      // One-dimensional weights of up to three nodes per direction.
      std::array<std::array<double, 3>, dim> w;
      std::array<std::array<double, 3>, dim> dw;
      // Axisymmetry, the radial direction: the hoop weights (w and dw are
      // then the radius-weighted averages, Basis1D::gimp_radial()).
      std::array<double, 3>                        hoop_weight;
      std::array<std::array<unsigned int, 3>, dim> index;
      std::array<unsigned int, dim>                count;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double h = grid.cell_size[d];
          const double x = position[d];
          count[d]       = 0;
          if (type == BasisType::standard_mpm)
            {
              long cell =
                static_cast<long>(std::floor((x - grid.lower[d]) / h));
              cell = std::max(0L, std::min<long>(cell, grid.n_cells[d] - 1));
              for (unsigned int k = 0; k < 2; ++k)
                {
                  const double dist = x - grid.node_coordinate(d, cell + k);
                  Basis1D::standard(
                    dist, h, k == 1, w[d][count[d]], dw[d][count[d]]);
                  if (d == 0 && grid.axisymmetric)
                    hoop_weight[count[d]] = w[d][count[d]] / x;
                  index[d][count[d]] = cell + k;
                  ++count[d];
                }
            }
          else
            {
              const double lp = half_length[d];
              Assert(lp > 0 && lp <= 0.5 * h,
                     ExcMessage("GIMP domain half-length out of range"));
              const double a     = std::max(x - lp, grid.lower[d]);
              const double b     = std::min(x + lp, grid.upper[d]);
              const long   first = std::max<long>(
                0, static_cast<long>(std::floor((a - grid.lower[d]) / h)));
              const long last = std::min<long>(grid.n_cells[d],
                                               static_cast<long>(std::ceil(
                                                 (b - grid.lower[d]) / h)));
              for (long i = first; i <= last; ++i)
                {
                  const double node = grid.node_coordinate(d, i);
                  double       weight, derivative, hoop = 0.;
                  if (d == 0 && grid.axisymmetric)
                    Basis1D::gimp_radial(x - node,
                                         h,
                                         lp,
                                         grid.lower[d] - node,
                                         grid.upper[d] - node,
                                         node,
                                         weight,
                                         derivative,
                                         hoop);
                  else
                    Basis1D::gimp(x - node,
                                  h,
                                  lp,
                                  grid.lower[d] - node,
                                  grid.upper[d] - node,
                                  weight,
                                  derivative);
                  if (weight == 0. && derivative == 0.)
                    continue;
                  AssertThrow(count[d] < 3,
                              ExcMessage("A GIMP domain couples to more than "
                                         "three nodes in one direction."));
                  if (d == 0)
                    hoop_weight[count[d]] = hoop;
                  w[d][count[d]]     = weight;
                  dw[d][count[d]]    = derivative;
                  index[d][count[d]] = i;
                  ++count[d];
                }
            }
        }

      if (grid.axisymmetric && type == BasisType::gimp)
        {
          double centroid = 0.;
          for (unsigned int k = 0; k < count[0]; ++k)
            centroid += w[0][k] * grid.node_coordinate(0, index[0][k]);
          support.radial_offset = position[0] - centroid;
        }
      // Tensor product (in axisymmetry with the radius-weighted radial
      // factors).
      support.n_nodes = 0;
      std::array<unsigned int, dim> k{};
      while (true)
        {
          std::array<unsigned int, dim> ijk;
          double                        weight = 1.;
          Tensor<1, dim>                gradient;
          for (unsigned int d = 0; d < dim; ++d)
            {
              ijk[d] = index[d][k[d]];
              weight *= w[d][k[d]];
            }
          for (unsigned int g = 0; g < dim; ++g)
            {
              double value = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                value *= (d == g) ? dw[d][k[d]] : w[d][k[d]];
              gradient[g] = value;
            }
          const unsigned int n = support.n_nodes++;
          if (grid.axisymmetric)
            {
              double hoop = hoop_weight[k[0]];
              for (unsigned int d = 1; d < dim; ++d)
                hoop *= w[d][k[d]];
              support.hoop_weights[n] = hoop;
            }
          support.nodes[n]     = grid.node_index(ijk);
          support.weights[n]   = weight;
          support.gradients[n] = gradient;

          unsigned int d = 0;
          for (; d < dim; ++d)
            {
              if (++k[d] < count[d])
                break;
              k[d] = 0;
            }
          if (d == dim)
            break;
        }
    }

    /**
     * @brief The weights that spread a force on one face of a point's
     * domain over the nodes of its support, @f$\frac{1}{|f|}\int_f N_v\,
     * dA@f$: the Q1 hat function at the face, @f$x_p \pm l_p@f$, in the
     * face's normal direction @p axis, and in the other directions the
     * weights of evaluate() (averages over the domain). They sum to one. A
     * traction integrated this way balances a uniform stress in the points
     * exactly (the divergence theorem on the domains). Standard MPM has no
     * domain: its weights are those of the point.
     *
     * @param position, half_length As given to evaluate() for @p support.
     * @param axis, sign The face: normal direction and side (+1 or -1).
     * @param support The point's support from evaluate().
     * @param[out] weights One weight per node of @p support.
     */
    void
    face_weights(
      const Point<dim>                                 &position,
      const Tensor<1, dim>                             &half_length,
      const unsigned int                                axis,
      const double                                      sign,
      const PointSupport<dim>                          &support,
      std::array<double, PointSupport<dim>::max_nodes> &weights) const
    {
      for (unsigned int n = 0; n < support.n_nodes; ++n)
        {
          if (type == BasisType::standard_mpm)
            {
              weights[n] = support.weights[n];
              continue;
            }
          std::uint64_t index  = support.nodes[n];
          double        weight = 1.;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const long i = static_cast<long>(index % grid.n_nodes(d));
              index /= grid.n_nodes(d);
              const double node = grid.node_coordinate(d, i);
              const double h    = grid.cell_size[d];
              if (d == axis)
                weight *=
                  Basis1D::hat(position[d] + sign * half_length[d] - node, h);
              else if (d == 0 && grid.axisymmetric)
                {
                  // The face is a ring: its radius-weighted average.
                  double w, derivative, hoop;
                  Basis1D::gimp_radial(position[d] - node,
                                       h,
                                       half_length[d],
                                       grid.lower[d] - node,
                                       grid.upper[d] - node,
                                       node,
                                       w,
                                       derivative,
                                       hoop);
                  weight *= w;
                }
              else
                {
                  double w, derivative;
                  Basis1D::gimp(position[d] - node,
                                h,
                                half_length[d],
                                grid.lower[d] - node,
                                grid.upper[d] - node,
                                w,
                                derivative);
                  weight *= w;
                }
            }
          weights[n] = weight;
        }
    }

  private:
    const CartesianGrid<dim> &grid;
    const BasisType           type;
  };
} // namespace impm

#endif
