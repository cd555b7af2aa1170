// The weights S_vp and gradients grad S_vp of BasisEvaluator in 1D, 2D and
// 3D, for GIMP (domain half-lengths lp = h/2, h/4 and h/6 in each direction)
// and for standard MPM, on Cartesian grids with non-unit and unequal cell
// sizes, at points at nodes, on cell faces, just off faces, at cell centres,
// where a GIMP domain ends exactly at a node, and (second set of points)
// closer than lp to, or exactly on, the grid boundary, where a GIMP domain is
// clipped to the grid. For each set of points the test checks
//   - the partition of unity, sum_v S_vp = 1, and that no weight is negative;
//   - the reproduction of linear fields, sum_v S_vp x_v = c_p, where c_p is
//     x_p for standard MPM and for an unclipped GIMP domain, and the centre of
//     the clipped domain otherwise (the GIMP weight is the hat function
//     averaged over the clipped domain, and the hat functions reproduce
//     linear fields inside the grid);
//   - sum_v grad S_vp = 0 and sum_v grad S_vp (x) x_v = identity (the
//     gradient of a linear field is reproduced, also for a clipped domain);
//   - for GIMP, that a clipped domain has the weights of an unclipped domain
//     [a, b] (the clipped one) on a grid extended by one cell on every side,
//     and each gradient against a central finite difference (step 1e-7 h),
//     relative to the largest gradient at that point, of those weights when
//     [a, b] is translated rigidly. basis_functions.h defines the GIMP
//     gradient as the hat function's derivative averaged over the clipped
//     domain, (N(b) - N(a))/(b - a), which is exactly this derivative; for an
//     unclipped domain it is the derivative of S_vp with respect to x_p. (For
//     a clipped domain, the derivative with respect to x_p is not the GIMP
//     gradient: only one end of the domain moves with the point.)
//   - for standard MPM, where the gradient is the piecewise-constant Q1
//     gradient of the point's cell (the cell containing the point; on an
//     interior face the upper one, on the upper grid boundary the last one),
//     the gradient against a finite difference in x_p taken inside that cell
//     (one-sided when the point is on a face of the cell).
//
// Finally, 1D GIMP weights and derivatives against hand calculations, on the
// grid [0, 4] with 8 cells, h = 0.5, from the three-piece formula of
// Bardenhagen and Kober (2004), with d = x_p - x_v:
//   S = 1 - (d^2 + lp^2)/(2 h lp)    for |d| < lp,
//   S = 1 - |d|/h                    for lp <= |d| < h - lp,
//   S = (h + lp - |d|)^2/(4 h lp)    for h - lp <= |d| < h + lp,
// and dS/dx_p = -d/(h lp), -sign(d)/h, -sign(d)(h + lp - |d|)/(2 h lp).
//   lp = h/4 = 0.125 (2 h lp = 0.125, 4 h lp = 0.25, h - lp = 0.375,
//   h + lp = 0.625):
//     x_p = 1.1: node 0.5, d = 0.6:  S = 0.025^2/0.25 = 0.0025,
//                                    dS/dx = -0.025/0.125 = -0.2
//                node 1.0, d = 0.1:  S = 1 - (0.01 + 0.015625)/0.125 = 0.795,
//                                    dS/dx = -0.1/0.0625 = -1.6
//                node 1.5, d = -0.4: S = 0.225^2/0.25 = 0.2025,
//                                    dS/dx = 0.225/0.125 = 1.8
//     x_p = 1.2: node 1.0, d = 0.2:  S = 1 - 0.2/0.5 = 0.6,  dS/dx = -2
//                node 1.5, d = -0.3: S = 1 - 0.3/0.5 = 0.4,  dS/dx = 2
//   lp = h/6 = 1/12 (2 h lp = 1/12, 4 h lp = 1/6, h + lp = 7/12):
//     x_p = 1.45: node 1.0, d = 9/20:   S = (7/12 - 9/20)^2 6 = 8/75
//                                       = 0.106667,
//                                       dS/dx = -(2/15) 12 = -1.6
//                 node 1.5, d = -1/20:  S = 1 - 12 (1/400 + 1/144)
//                                       = 133/150 = 0.886667,
//                                       dS/dx = (1/20) 24 = 1.2
//                 node 2.0, d = -11/20: S = (7/12 - 11/20)^2 6 = 1/150
//                                       = 0.00666667,
//                                       dS/dx = (1/30) 12 = 0.4
//   lp = h/4, clipped at the lower grid boundary: x_p = 0.05, domain
//   [a, b] = [0, 0.175] (instead of [-0.075, 0.175]); the mean of the hat
//   functions over [a, b], and the mean of their derivatives,
//   (N(b) - N(a))/(b - a), give
//     node 0.0: S = 1 - (a + b)/(2h) = 0.825,
//               grad S = (0.65 - 1)/0.175 = -2 (= -1/h)
//     node 0.5: S = (a + b)/(2h) = 0.175,
//               grad S = (0.35 - 0)/0.175 = 2 (= 1/h)
//   (the derivative with respect to x_p would be -1 and 1).
//   Standard MPM at x_p = 1.1: node 1.0: S = 0.8, node 1.5: S = 0.2,
//   dS/dx = -1/h = -2 and 1/h = 2.

#include <impm/basis/basis_functions.h>

#include <algorithm>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <vector>

#include "tests.h"

using namespace impm;

namespace
{
  template <int dim>
  Point<dim>
  node_position(const CartesianGrid<dim> &grid, std::uint64_t index)
  {
    Point<dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      {
        x[d] = grid.node_coordinate(d, index % grid.n_nodes(d));
        index /= grid.n_nodes(d);
      }
    return x;
  }

  /** Weights by node index; a node that is not listed has weight zero. */
  template <int dim>
  std::map<std::uint64_t, double>
  weights_at(const BasisEvaluator<dim> &evaluator,
             const Point<dim>          &x,
             const Tensor<1, dim>      &half_length)
  {
    PointSupport<dim> support;
    evaluator.evaluate(x, half_length, support);
    std::map<std::uint64_t, double> weights;
    for (unsigned int n = 0; n < support.n_nodes; ++n)
      weights[support.nodes[n]] = support.weights[n];
    return weights;
  }

  double
  weight_of(const std::map<std::uint64_t, double> &weights,
            const std::uint64_t                    node)
  {
    const auto it = weights.find(node);
    return it == weights.end() ? 0. : it->second;
  }

  struct Errors
  {
    double partition         = 0.;
    double negative          = 0.;
    double linear            = 0.;
    double clipped_domain    = 0.;
    double gradient_sum      = 0.;
    double gradient_linear   = 0.;
    double finite_difference = 0.;
  };

  /** The index on @p extended of node @p index of @p grid. */
  template <int dim>
  std::uint64_t
  extended_index(const CartesianGrid<dim> &grid,
                 const CartesianGrid<dim> &extended,
                 std::uint64_t             index)
  {
    std::array<unsigned int, dim> ijk;
    for (unsigned int d = 0; d < dim; ++d)
      {
        ijk[d] = index % grid.n_nodes(d) + 1;
        index /= grid.n_nodes(d);
      }
    return extended.node_index(ijk);
  }

  template <int dim>
  void
  check_point(const CartesianGrid<dim>  &grid,
              const BasisEvaluator<dim> &evaluator,
              const CartesianGrid<dim>  &extended_grid,
              const BasisEvaluator<dim> &extended_evaluator,
              const BasisType            type,
              const Point<dim>          &x,
              const Tensor<1, dim>      &half_length,
              Errors                    &errors)
  {
    PointSupport<dim> support;
    evaluator.evaluate(x, half_length, support);

    // The centre and half-lengths of the domain clipped to the grid.
    Point<dim>     centre              = x;
    Tensor<1, dim> clipped_half_length = half_length;
    if (type == BasisType::gimp)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double a = std::max(x[d] - half_length[d], grid.lower[d]);
          const double b = std::min(x[d] + half_length[d], grid.upper[d]);
          centre[d]      = (a + b) / 2.;
          clipped_half_length[d] = (b - a) / 2.;
        }

    double         sum = 0.;
    Point<dim>     first_moment;
    Tensor<1, dim> gradient_sum;
    Tensor<2, dim> gradient_moment;
    double         largest_gradient = 0.;
    for (unsigned int n = 0; n < support.n_nodes; ++n)
      {
        const Point<dim> xv = node_position(grid, support.nodes[n]);
        sum += support.weights[n];
        errors.negative = std::max(errors.negative, -support.weights[n]);
        first_moment += support.weights[n] * xv;
        gradient_sum += support.gradients[n];
        gradient_moment += outer_product(support.gradients[n], xv);
        for (unsigned int d = 0; d < dim; ++d)
          largest_gradient =
            std::max(largest_gradient, std::abs(support.gradients[n][d]));
      }
    errors.partition = std::max(errors.partition, std::abs(sum - 1.));
    for (unsigned int d = 0; d < dim; ++d)
      {
        errors.linear =
          std::max(errors.linear, std::abs(first_moment[d] - centre[d]));
        errors.gradient_sum =
          std::max(errors.gradient_sum, std::abs(gradient_sum[d]));
        for (unsigned int e = 0; e < dim; ++e)
          errors.gradient_linear =
            std::max(errors.gradient_linear,
                     std::abs(gradient_moment[d][e] - (d == e ? 1. : 0.)));
      }

    // The weights and gradients by node index: for GIMP on the extended
    // grid, where the clipped domain is an unclipped one.
    std::map<std::uint64_t, double>         weight;
    std::map<std::uint64_t, Tensor<1, dim>> gradient;
    for (unsigned int n = 0; n < support.n_nodes; ++n)
      {
        const std::uint64_t node =
          (type == BasisType::gimp) ?
            extended_index(grid, extended_grid, support.nodes[n]) :
            support.nodes[n];
        weight[node]   = support.weights[n];
        gradient[node] = support.gradients[n];
      }
    if (type == BasisType::gimp)
      {
        const auto reference =
          weights_at(extended_evaluator, centre, clipped_half_length);
        for (const auto &entry : reference)
          errors.clipped_domain =
            std::max(errors.clipped_domain,
                     std::abs(entry.second - weight_of(weight, entry.first)));
        for (const auto &entry : weight)
          errors.clipped_domain =
            std::max(errors.clipped_domain,
                     std::abs(entry.second -
                              weight_of(reference, entry.first)));
      }

    // Finite differences, direction by direction.
    for (unsigned int g = 0; g < dim; ++g)
      {
        const double h     = grid.cell_size[g];
        const double delta = 1e-7 * h;
        // Offsets of the two samples: central for GIMP, inside the cell for
        // standard MPM.
        double minus = -delta, plus = delta;
        if (type == BasisType::standard_mpm)
          {
            const long cell =
              std::max(0L,
                       std::min<long>(grid.n_cells[g] - 1,
                                      static_cast<long>(std::floor(
                                        (x[g] - grid.lower[g]) / h))));
            const double cell_lower = grid.node_coordinate(g, cell);
            const double cell_upper = grid.node_coordinate(g, cell + 1);
            if (x[g] - delta < cell_lower)
              minus = 0.;
            else if (x[g] + delta > cell_upper)
              plus = 0.;
          }
        Point<dim> x_minus = centre, x_plus = centre;
        x_minus[g] += minus;
        x_plus[g] += plus;
        const auto w_minus =
          (type == BasisType::gimp) ?
            weights_at(extended_evaluator, x_minus, clipped_half_length) :
            weights_at(evaluator, x_minus, half_length);
        const auto w_plus =
          (type == BasisType::gimp) ?
            weights_at(extended_evaluator, x_plus, clipped_half_length) :
            weights_at(evaluator, x_plus, half_length);

        std::map<std::uint64_t, double> gradient_g;
        for (const auto &entry : w_minus)
          gradient_g[entry.first] = 0.;
        for (const auto &entry : w_plus)
          gradient_g[entry.first] = 0.;
        for (const auto &entry : gradient)
          gradient_g[entry.first] = entry.second[g];
        for (const auto &entry : gradient_g)
          {
            const double fd = (weight_of(w_plus, entry.first) -
                               weight_of(w_minus, entry.first)) /
                              (plus - minus);
            errors.finite_difference =
              std::max(errors.finite_difference,
                       std::abs(fd - entry.second) / largest_gradient);
          }
      }
  }

  template <int dim>
  void
  check_set(const CartesianGrid<dim>      &grid,
            const BasisType                type,
            const Tensor<1, dim>          &half_length,
            const std::string             &name,
            const std::vector<Point<dim>> &points,
            const std::string             &description)
  {
    const BasisEvaluator<dim> evaluator(grid, type);

    // The grid extended by one cell on every side.
    CartesianGrid<dim>            extended_grid;
    std::array<unsigned int, dim> cells;
    for (unsigned int d = 0; d < dim; ++d)
      cells[d] = grid.n_cells[d] + 2;
    extended_grid.initialize(grid.lower - grid.cell_size,
                             grid.upper + grid.cell_size,
                             cells);
    const BasisEvaluator<dim> extended_evaluator(extended_grid, type);

    Errors errors;
    for (const auto &x : points)
      check_point(grid,
                  evaluator,
                  extended_grid,
                  extended_evaluator,
                  type,
                  x,
                  half_length,
                  errors);

    std::cout << dim << "D, " << name << ", " << points.size() << " points "
              << description << ":" << std::endl;
    impm_tests::check_below("  |sum_v S_vp - 1|", errors.partition, 1e-12);
    impm_tests::check_below("  -min_v S_vp", errors.negative, 1e-14);
    impm_tests::check_below("  |sum_v S_vp x_v - c_p|", errors.linear, 1e-12);
    impm_tests::check_below("  |sum_v grad S_vp|", errors.gradient_sum, 1e-10);
    impm_tests::check_below("  |sum_v grad S_vp (x) x_v - I|",
                            errors.gradient_linear,
                            1e-10);
    if (type == BasisType::gimp)
      impm_tests::check_below("  |S_vp - S_vp of the clipped domain [a, b]|",
                              errors.clipped_domain,
                              1e-12);
    impm_tests::check_below(type == BasisType::gimp ?
                              "  relative error of the gradients against "
                              "central differences in the position of [a, b]" :
                              "  relative error of the gradients against "
                              "differences inside the cell",
                            errors.finite_difference,
                            1e-6);
  }

  /** All points whose coordinates (in units of h) come from @p samples. */
  template <int dim>
  std::vector<Point<dim>>
  points_from(const CartesianGrid<dim>                      &grid,
              const std::array<std::vector<double>, dim>    &samples,
              const std::function<bool(const Point<dim> &)> &keep)
  {
    std::vector<Point<dim>>       points;
    std::array<unsigned int, dim> k{};
    while (true)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = grid.lower[d] + samples[d][k[d]] * grid.cell_size[d];
        if (keep(x))
          points.push_back(x);
        unsigned int d = 0;
        for (; d < dim; ++d)
          {
            if (++k[d] < samples[d].size())
              break;
            k[d] = 0;
          }
        if (d == dim)
          break;
      }
    return points;
  }

  template <int dim>
  void
  check_grid(const Point<dim>                    &upper,
             const std::array<unsigned int, dim> &cells)
  {
    CartesianGrid<dim> grid;
    grid.initialize(Point<dim>(), upper, cells);

    // Inside: on faces and nodes (1), cell centres (1.5, where an lp = h/2
    // domain ends exactly at two nodes), 1e-3 h off a face on either side,
    // a generic point, and a point whose lp = h/4 domain starts at a node.
    std::array<std::vector<double>, dim> inside, boundary;
    std::vector<double>                  near_boundary;
    for (unsigned int d = 0; d < dim; ++d)
      {
        inside[d] = {1., 1.3, 1.5, 2.001, 2.999, 3.25};
        // Near the boundary: on it, 0.05 h and 0.1 h inside (closer than
        // h/6), and one interior coordinate.
        const double n = grid.n_cells[d];
        boundary[d]    = {0., 0.1, 1.5, n - 0.05, n};
      }
    const auto all = [](const Point<dim> &) { return true; };
    // Keep the points with at least one coordinate near the boundary.
    const auto near = [&grid](const Point<dim> &x) {
      for (unsigned int d = 0; d < dim; ++d)
        if (x[d] - grid.lower[d] < 0.2 * grid.cell_size[d] ||
            grid.upper[d] - x[d] < 0.2 * grid.cell_size[d])
          return true;
      return false;
    };
    const std::vector<Point<dim>> inside_points =
      points_from<dim>(grid, inside, all);
    const std::vector<Point<dim>> boundary_points =
      points_from<dim>(grid, boundary, near);

    const std::array<std::pair<double, std::string>, 3> fractions = {
      {{2., "lp = h/2"}, {4., "lp = h/4"}, {6., "lp = h/6"}}};
    for (const auto &fraction : fractions)
      {
        const Tensor<1, dim> half_length = grid.cell_size / fraction.first;
        check_set(grid,
                  BasisType::gimp,
                  half_length,
                  "GIMP, " + fraction.second,
                  inside_points,
                  "inside the grid");
        check_set(grid,
                  BasisType::gimp,
                  half_length,
                  "GIMP, " + fraction.second,
                  boundary_points,
                  "with domains clipped at the grid boundary");
      }
    check_set(grid,
              BasisType::standard_mpm,
              Tensor<1, dim>(),
              "standard MPM",
              inside_points,
              "inside the grid");
    check_set(grid,
              BasisType::standard_mpm,
              Tensor<1, dim>(),
              "standard MPM",
              boundary_points,
              "near or on the grid boundary");
  }

  /** 1D weights and derivatives against the hand calculation at the top. */
  void
  check_by_hand()
  {
    CartesianGrid<1> grid;
    grid.initialize(Point<1>(0.), Point<1>(4.), {{8}});

    struct Case
    {
      BasisType           type;
      double              lp;
      double              x;
      std::vector<double> nodes, weights, derivatives;
    };
    const std::vector<Case> cases = {
      {BasisType::gimp,
       0.125,
       1.1,
       {0.5, 1.0, 1.5},
       {0.0025, 0.795, 0.2025},
       {-0.2, -1.6, 1.8}},
      {BasisType::gimp, 0.125, 1.2, {1.0, 1.5}, {0.6, 0.4}, {-2., 2.}},
      {BasisType::gimp,
       0.5 / 6.,
       1.45,
       {1.0, 1.5, 2.0},
       {8. / 75., 133. / 150., 1. / 150.},
       {-1.6, 1.2, 0.4}},
      {BasisType::gimp, 0.125, 0.05, {0., 0.5}, {0.825, 0.175}, {-2., 2.}},
      {BasisType::standard_mpm, 0., 1.1, {1.0, 1.5}, {0.8, 0.2}, {-2., 2.}}};

    std::cout << "1D by hand, h = 0.5:" << std::endl;
    for (const auto &c : cases)
      {
        const BasisEvaluator<1> evaluator(grid, c.type);
        PointSupport<1>         support;
        Tensor<1, 1>            half_length;
        half_length[0] = c.lp;
        evaluator.evaluate(Point<1>(c.x), half_length, support);
        std::cout << "  ";
        if (c.type == BasisType::gimp)
          std::cout << "GIMP, lp = " << c.lp;
        else
          std::cout << "standard MPM";
        std::cout << ", x_p = " << c.x << ": " << support.n_nodes << " nodes"
                  << std::endl;
        bool agree = (support.n_nodes == c.nodes.size());
        for (unsigned int n = 0; n < support.n_nodes; ++n)
          {
            const double xv = node_position(grid, support.nodes[n])[0];
            std::cout << "    node " << xv << ": S = " << support.weights[n]
                      << ", grad S = " << support.gradients[n][0] << std::endl;
            const auto it = std::find_if(c.nodes.begin(),
                                         c.nodes.end(),
                                         [xv](const double node) {
                                           return std::abs(node - xv) < 1e-12;
                                         });
            if (it == c.nodes.end())
              {
                agree = false;
                continue;
              }
            const unsigned int i = it - c.nodes.begin();
            agree =
              agree && std::abs(support.weights[n] - c.weights[i]) < 1e-12 &&
              std::abs(support.gradients[n][0] - c.derivatives[i]) < 1e-12;
          }
        std::cout << "    agrees with the hand calculation to 1e-12: "
                  << (agree ? "yes" : "NO") << std::endl;
      }
  }
} // namespace



int
main()
{
  std::cout << std::setprecision(6);
  check_grid<1>(Point<1>(4.), {{8}});
  check_grid<2>(Point<2>(5., 3.), {{4, 6}});
  check_grid<3>(Point<3>(4., 3., 5.), {{8, 6, 4}});
  check_by_hand();
}
