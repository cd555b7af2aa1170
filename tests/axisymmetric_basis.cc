// Axisymmetric weights between material points and nodes (Grid/Axisymmetric),
// on the meridian grid [0, 2] x [0, 1] with 4 x 2 cells (h = 0.5), against a
// midpoint rule with 20,000 intervals between each pair of kinks (nodes)
// in each point's domain (independent
// of the closed forms in Basis1D::gimp_radial()):
//   GIMP, with the domain [a, b] x [c, d] (clipped at the axis r = 0):
//     S_v      = int N_v r / int r,
//     dS_v/dr  = int (dN_v/dr) r / int r,  dS_v/dz = int (dN_v/dz) r / int r,
//     H_v      = int N_v / int r            (the hoop weight, N_v/r averaged
//                                            over the ring),
//     and the point's offset from its ring's centroid, r_p - sum_v S_v r_v,
//     equal to r_p - int r^2 / int r;
//   standard MPM: H_v = N_v(x_p) / r_p and no offset.
// Then the identities that make a uniform stress balance and a linear field
// exact: sum_v S_v = 1, sum_v dS_v/dr r_v = 1, sum_v H_v r_v = 1 (u_r = r
// gives u_r / r = 1 everywhere), sum_v dS_v/dr = 0.
// Points: inside a cell, on a domain that spans a node, next to the axis with
// a domain that touches it (r_p = lp) and one that is capped by it.

#include <impm/basis/basis_functions.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

using namespace impm;

namespace
{
  /** Hat function of node @p node at @p x (cell size @p h). */
  double
  hat(const double x, const double node, const double h)
  {
    return std::max(0., 1. - std::abs(x - node) / h);
  }

  /** Derivative of the hat function, zero at its kinks' measure-zero set. */
  double
  hat_derivative(const double x, const double node, const double h)
  {
    const double d = x - node;
    if (std::abs(d) >= h)
      return 0.;
    return d < 0. ? 1. / h : -1. / h;
  }

  void
  check_point(const CartesianGrid<2> &grid,
              const BasisType         type,
              const Point<2>         &x,
              const Tensor<1, 2>     &lp)
  {
    const BasisEvaluator<2> evaluator(grid, type);
    PointSupport<2>         support;
    evaluator.evaluate(x, lp, support);
    const double h = grid.cell_size[0];
    // The domain, clipped at the grid (here: at the axis).
    const double       a             = std::max(x[0] - lp[0], grid.lower[0]);
    const double       b             = std::min(x[0] + lp[0], grid.upper[0]);
    const double       c             = std::max(x[1] - lp[1], grid.lower[1]);
    const double       d             = std::min(x[1] + lp[1], grid.upper[1]);
    const unsigned int n_intervals   = 200000;
    double             largest_error = 0.;
    double sum_weights = 0., sum_radial_gradient = 0., linear_gradient = 0.,
           linear_hoop    = 0.;
    double centroid_nodes = 0.;
    for (unsigned int n = 0; n < support.n_nodes; ++n)
      {
        const std::uint64_t index = support.nodes[n];
        const double rv = grid.node_coordinate(0, index % grid.n_nodes(0));
        const double zv = grid.node_coordinate(1, index / grid.n_nodes(0));
        double       S, dSr, dSz, H;
        if (type == BasisType::gimp)
          {
            // Piecewise midpoint rules between the kinks (the nodes).
            const auto integrate = [&](const double lower,
                                       const double upper,
                                       const auto  &f) {
              std::vector<double> breaks = {lower, upper};
              for (double node = 0.; node < 3.; node += h)
                if (node > lower && node < upper)
                  breaks.push_back(node);
              std::sort(breaks.begin(), breaks.end());
              double sum = 0.;
              for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
                {
                  const double step = (breaks[k + 1] - breaks[k]) / n_intervals;
                  for (unsigned int i = 0; i < n_intervals; ++i)
                    sum += f(breaks[k] + (i + 0.5) * step) * step;
                }
              return sum;
            };
            const double int_r = integrate(a, b, [](double r) { return r; });
            const double int_Nr =
              integrate(a, b, [&](double r) { return hat(r, rv, h) * r; });
            const double int_dNr = integrate(a, b, [&](double r) {
              return hat_derivative(r, rv, h) * r;
            });
            const double int_N =
              integrate(a, b, [&](double r) { return hat(r, rv, h); });
            const double int_Nz =
              integrate(c, d, [&](double z) { return hat(z, zv, h); });
            const double int_dNz = integrate(c, d, [&](double z) {
              return hat_derivative(z, zv, h);
            });
            S                    = int_Nr / int_r * int_Nz / (d - c);
            dSr                  = int_dNr / int_r * int_Nz / (d - c);
            dSz                  = int_Nr / int_r * int_dNz / (d - c);
            H                    = int_N / int_r * int_Nz / (d - c);
          }
        else
          {
            S   = hat(x[0], rv, h) * hat(x[1], zv, h);
            dSr = support.gradients[n][0]; // standard MPM: not in question
            dSz = support.gradients[n][1];
            H   = S / x[0];
          }
        largest_error = std::max({largest_error,
                                  std::abs(support.weights[n] - S),
                                  std::abs(support.gradients[n][0] - dSr) * h,
                                  std::abs(support.gradients[n][1] - dSz) * h,
                                  std::abs(support.hoop_weights[n] - H) * h});
        sum_weights += support.weights[n];
        sum_radial_gradient += support.gradients[n][0];
        linear_gradient += support.gradients[n][0] * rv;
        linear_hoop += support.hoop_weights[n] * rv;
        centroid_nodes += support.weights[n] * rv;
      }
    double offset_error = std::abs(support.radial_offset);
    if (type == BasisType::gimp)
      offset_error =
        std::abs(support.radial_offset -
                 (x[0] - 2. / 3. * (b * b * b - a * a * a) / (b * b - a * a)));
    std::cout << (type == BasisType::gimp ? "GIMP" : "standard MPM")
              << ", x_p = (" << x[0] << ", " << x[1] << "), lp_r = " << lp[0]
              << ": " << support.n_nodes << " nodes" << std::endl
              << "  S, grad S, H against the quadrature (scaled by h) to 1e-8: "
              << (largest_error < 1e-8 ? "yes" : "NO") << std::endl
              << "  offset from the ring's centroid to 1e-12: "
              << (offset_error < 1e-12 ? "yes" : "NO") << std::endl
              << "  sum S = 1, sum dS/dr = 0, sum dS/dr r_v = 1, "
                 "sum H r_v = 1 to 1e-12: "
              << (std::abs(sum_weights - 1.) < 1e-12 &&
                      std::abs(sum_radial_gradient) * h < 1e-12 &&
                      std::abs(linear_gradient - 1.) < 1e-12 &&
                      std::abs(linear_hoop - 1.) < 1e-12 ?
                    "yes" :
                    "NO")
              << std::endl
              << "  offset (r_p - sum S r_v) / h = "
              << (x[0] - centroid_nodes) / h << std::endl;
  }
} // namespace



int
main()
{
  std::cout << std::setprecision(6);
  CartesianGrid<2> grid;
  grid.initialize(Point<2>(0., 0.), Point<2>(2., 1.), {{4, 2}});
  grid.axisymmetric = true;
  for (const BasisType type : {BasisType::gimp, BasisType::standard_mpm})
    {
      // Inside a cell, domain a quarter cell.
      check_point(grid,
                  type,
                  Point<2>(0.875, 0.375),
                  Tensor<1, 2>({0.125, 0.125}));
      // Spanning the node r = 1 and z = 0.5.
      check_point(grid, type, Point<2>(1.05, 0.52), Tensor<1, 2>({0.2, 0.15}));
      // Next to the axis: the domain touches it.
      check_point(grid,
                  type,
                  Point<2>(0.125, 0.625),
                  Tensor<1, 2>({0.125, 0.125}));
      // Nearer than its half-length: the domain is capped at the axis.
      check_point(grid, type, Point<2>(0.01, 0.25), Tensor<1, 2>({0.1, 0.25}));
      // Squeezed far towards the axis.
      check_point(grid, type, Point<2>(0.003, 0.8), Tensor<1, 2>({0.003, 0.1}));
    }
}
