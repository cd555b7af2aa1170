#ifndef impm_basis_basis_1d_h
#define impm_basis_basis_1d_h

#include <algorithm>
#include <cmath>

namespace impm
{
  /**
   * @brief One-dimensional weights between one node and one material point.
   *
   * All functions take the distance `d = x_p - x_v` of the point from the node
   * and return the weight and its derivative with respect to the point's
   * position `x_p` (which is the derivative with respect to the start-of-step
   * coordinate in the formulation).
   */
  namespace Basis1D
  {
    /**
     * @brief The Q1 hat function of a node, @f$N(d) = \max(0, 1-|d|/h)@f$.
     */
    inline double
    hat(const double d, const double h)
    {
      const double a = std::abs(d);
      return (a < h) ? 1. - a / h : 0.;
    }

    /**
     * @brief The integral of the hat function from @f$-\infty@f$ to @p t.
     */
    inline double
    hat_integral(const double t, const double h)
    {
      if (t <= -h)
        return 0.;
      if (t <= 0.)
        return (t + h) * (t + h) / (2. * h);
      if (t < h)
        return h - (h - t) * (h - t) / (2. * h);
      return h;
    }

    /**
     * @brief The first moment of the hat function from @f$-\infty@f$ to
     * @p t, @f$\int_{-\infty}^t s\,N(s)\,ds@f$ (zero for @f$t \ge h@f$).
     */
    inline double
    hat_moment(const double t, const double h)
    {
      if (t <= -h)
        return 0.;
      const double s = std::min(t, h);
      return s * s / 2. - std::abs(s) * s * s / (3. * h) - h * h / 6.;
    }

    /**
     * @brief Axisymmetric GIMP: the averages over a point's domain in the
     * radial direction weighted by the radius, as the volume of the ring
     * the domain sweeps weighs them. With @f$[a, b]@f$ the domain clipped
     * as in gimp() and @f$r = x_v + s@f$ the radius (@p node is
     * @f$x_v@f$):
     * @f$\bar N' = \int_a^b N'\,r\,ds / \int_a^b r\,ds@f$ (the radial
     * gradient), @f$\bar N = \int_a^b N\,r\,ds / \int_a^b r\,ds@f$ (the
     * factor of the axial gradient) and @f$\bar N_\theta = \int_a^b
     * N\,ds / \int_a^b r\,ds@f$ (the hoop weight, the average of
     * @f$N/r@f$).
     *
     * With these a uniform stress in the points balances exactly at every
     * interior node, wherever the domains lie against the nodes, and a
     * linear radial displacement gives the exact radial, axial and hoop
     * strains. (The unweighted averages do not: the force of a domain
     * across a node then misses @f$\sigma_{rr}\int_a^b N'(r - r_p)\,ds@f$.)
     *
     * @param d, h, lp, lower, upper As for gimp().
     * @param node The node's radius @f$x_v@f$.
     * @param[out] weighted The radius-weighted average of the hat function.
     * @param[out] weighted_derivative That of its derivative.
     * @param[out] hoop_weight The average of @f$N/r@f$.
     */
    inline void
    gimp_radial(const double d,
                const double h,
                const double lp,
                const double lower,
                const double upper,
                const double node,
                double      &weighted,
                double      &weighted_derivative,
                double      &hoop_weight)
    {
      const double a        = std::max(d - lp, lower);
      const double b        = std::min(d + lp, upper);
      const double integral = hat_integral(b, h) - hat_integral(a, h);
      const double moment   = hat_moment(b, h) - hat_moment(a, h);
      // The integral of r over the domain.
      const double radius_integral = node * (b - a) + 0.5 * (b * b - a * a);
      // int N' s ds = [s N]_a^b - int N ds.
      const double derivative_moment = b * hat(b, h) - a * hat(a, h) - integral;
      weighted = (node * integral + moment) / radius_integral;
      weighted_derivative =
        (node * (hat(b, h) - hat(a, h)) + derivative_moment) / radius_integral;
      hoop_weight = integral / radius_integral;
    }

    /**
     * @brief GIMP weight: the hat function averaged over the domain
     * @f$[d-l_p, d+l_p]@f$ clipped to @f$[lower, upper]@f$ (the grid, in
     * coordinates relative to the node).
     *
     * Clipping the domain at the grid boundary keeps the partition of unity
     * when a domain reaches past the outermost nodes. For an unclipped domain
     * with @f$l_p \le h/2@f$ this is the three-piece formula of Bardenhagen
     * and Kober (2004).
     *
     * The gradient is the hat function's derivative averaged over the same
     * (clipped) domain, @f$(N(b)-N(a))/(b-a)@f$. For an unclipped domain it
     * equals the derivative of the weight with respect to @f$x_p@f$; for a
     * clipped one it is not, and it is the one that reproduces the gradient
     * of a linear field exactly (the derivative of the clipped weight would
     * halve it).
     *
     * @param d Point position minus node position.
     * @param h Cell size in this direction.
     * @param lp Half-length of the point's domain in this direction.
     * @param lower Lower end of the grid, relative to the node.
     * @param upper Upper end of the grid, relative to the node.
     * @param[out] weight The weight @f$S_{vp}@f$.
     * @param[out] derivative The domain-averaged gradient.
     */
    inline void
    gimp(const double d,
         const double h,
         const double lp,
         const double lower,
         const double upper,
         double      &weight,
         double      &derivative)
    {
      const bool   clip_low  = (d - lp < lower);
      const bool   clip_high = (d + lp > upper);
      const double a         = clip_low ? lower : d - lp;
      const double b         = clip_high ? upper : d + lp;
      const double length    = b - a;
      const double integral  = hat_integral(b, h) - hat_integral(a, h);
      weight                 = integral / length;
      derivative             = (hat(b, h) - hat(a, h)) / length;
    }

    /**
     * @brief Standard MPM weight: the hat function and its derivative,
     * where the derivative is that of the point's cell: @f$-1/h@f$ for the
     * cell's lower node and @f$+1/h@f$ for its upper node.
     *
     * @param d Point position minus node position.
     * @param h Cell size.
     * @param node_is_upper Whether the node is the upper node of the point's
     *   cell in this direction.
     * @param[out] weight The weight.
     * @param[out] derivative Its derivative with respect to @f$x_p@f$.
     */
    inline void
    standard(const double d,
             const double h,
             const bool   node_is_upper,
             double      &weight,
             double      &derivative)
    {
      weight     = hat(d, h);
      derivative = node_is_upper ? 1. / h : -1. / h;
    }
  } // namespace Basis1D
} // namespace impm

#endif
