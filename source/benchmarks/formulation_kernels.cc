// The per-point cost of the two statements of equilibrium, free of the
// matrix insertion, vector communication and timer overheads that make up
// most of a small run's assembly phase.
//
// For 2D and 3D, supports of 2, 2-3 and 3 nodes per direction (standard
// MPM, GIMP inside a cell, GIMP across faces) and elastic and plastic
// states, it times on the same synthetic points (fixed seed):
//   residual:  the nodal forces of a point (the updated Lagrangian form maps
//              its gradients here, once per iterate),
//   stiffness: the material tangent and the dense point stiffness (the
//              updated Lagrangian form reuses the mapped gradients),
// and prints nanoseconds per point (median of the trials) and the ratio
// updated Lagrangian / previously converged for one Newton iteration
// (residual + stiffness).
//
// A second table times the point stiffness kernel before and after its
// rewrite (issue 10): "before" is the node-major kernel of the releases up
// to the solver split (kept here as the reference, all entries, innermost
// loop over the d components); "after" is PointStiffness (component-major,
// vectorised over nodes), with all entries and with the major symmetry the
// Hencky and von Mises tangents have. Each is timed alone on stored
// tangents and with the tangent's evaluation (previously converged form),
// and the largest difference of the after-matrix from the before-matrix is
// printed relative to its largest entry.
//
// Usage: impm-formulation-kernels [points] [trials]

#include <impm/basis/basis_functions.h>
#include <impm/mechanics/equilibrium_forms.h>
#include <impm/mechanics/point_stiffness.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

using namespace impm;

namespace
{
  /**
   * The point stiffness kernel before issue 10: node-major matrix
   * (DoF = node * dim + component), all entries, innermost loop over the
   * components. The reference for the timings and the differences.
   */
  template <int dim>
  void
  add_point_stiffness_before(const Tensor<4, dim> &A,
                             const Tensor<1, dim> *gradients,
                             const unsigned int    n_nodes,
                             double               *matrix)
  {
    const unsigned int n = n_nodes * dim;
    for (unsigned int v = 0; v < n_nodes; ++v)
      {
        double B[dim][dim][dim] = {};
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int q = 0; q < dim; ++q)
                B[i][k][q] += gradients[v][j] * A[i][j][k][q];
        for (unsigned int i = 0; i < dim; ++i)
          {
            double *row = matrix + (v * dim + i) * n;
            for (unsigned int w = 0; w < n_nodes; ++w)
              for (unsigned int k = 0; k < dim; ++k)
                {
                  double value = 0.;
                  for (unsigned int q = 0; q < dim; ++q)
                    value += B[i][k][q] * gradients[w][q];
                  row[w * dim + k] += value;
                }
          }
      }
  }



  /** The synthetic state of one point. */
  template <int dim>
  struct SyntheticPoint
  {
    std::array<Tensor<1, dim>, PointSupport<dim>::max_nodes> gradients;
    std::array<Tensor<1, dim>, PointSupport<dim>::max_nodes> mapped_gradients;
    Tensor<2, dim>                                           dF_inverse;
    ConstitutiveUpdate                                       update;
    Tensor<4, dim> tangent; // previously converged, V = 1
  };

  /**
   * Time each of @p kernels over all points, @p trials times, taking the
   * kernels in turn within a trial (so that a drift of the machine's speed
   * affects all alike); returns the medians in ns per point.
   */
  std::vector<double>
  time_per_point(const unsigned int                                    n_points,
                 const unsigned int                                    trials,
                 const std::vector<std::function<void(unsigned int)>> &kernels)
  {
    std::vector<std::vector<double>> times(kernels.size());
    for (unsigned int t = 0; t < trials; ++t)
      for (unsigned int k = 0; k < kernels.size(); ++k)
        {
          const auto start = std::chrono::steady_clock::now();
          for (unsigned int p = 0; p < n_points; ++p)
            kernels[k](p);
          const auto end = std::chrono::steady_clock::now();
          times[k].push_back(
            std::chrono::duration<double, std::nano>(end - start).count() /
            n_points);
        }
    std::vector<double> medians;
    for (std::vector<double> &kernel_times : times)
      {
        std::sort(kernel_times.begin(), kernel_times.end());
        medians.push_back(kernel_times[kernel_times.size() / 2]);
      }
    return medians;
  }



  /**
   * @brief Append one row to each table: the per-point times @p ns of the
   * two statements (form table) and of the stiffness kernels (kernel
   * table), with the kernels' largest relative difference.
   */
  void
  append_rows(const unsigned int         dim,
              const unsigned int         n_nodes,
              const std::string         &state,
              const unsigned int         percent_plastic,
              const std::vector<double> &ns,
              const bool                 finite_checksum,
              const bool                 symmetric,
              const double               relative_difference,
              std::string               &form_table,
              std::string               &kernel_table)
  {
    char line[512];
    std::snprintf(line,
                  sizeof(line),
                  "| %u | %u | %s (%u%% plastic) | %.0f | %.0f | %.0f | %.0f | "
                  "%.3f |%s\n",
                  dim,
                  n_nodes,
                  state.c_str(),
                  percent_plastic,
                  ns[0],
                  ns[1],
                  ns[2],
                  ns[3],
                  (ns[1] + ns[3]) / (ns[0] + ns[2]),
                  finite_checksum ? "" : " (non-finite checksum)");
    form_table += line;
    std::snprintf(line,
                  sizeof(line),
                  "| %u | %u | %s | %.0f | %.0f | %.0f | %.2f | %.0f | %.0f | "
                  "%.2f | %.1e |\n",
                  dim,
                  n_nodes,
                  state.c_str(),
                  ns[5],
                  ns[6],
                  ns[7],
                  ns[5] / (symmetric ? ns[7] : ns[6]),
                  ns[4],
                  ns[2],
                  ns[4] / ns[2],
                  relative_difference);
    kernel_table += line;
  }



  /**
   * @brief @p n_points synthetic points on a support of @p n_nodes: random
   * gradients, a random start of strain @p strain and a random increment of
   * a fifth of it, updated by @p material; @p n_plastic counts the plastic
   * ones.
   */
  template <int dim>
  std::vector<SyntheticPoint<dim>>
  make_points(const unsigned int n_nodes,
              const Material    &material,
              const double       strain,
              const unsigned int n_points,
              std::mt19937      &random,
              unsigned int      &n_plastic)
  {
    std::uniform_real_distribution<double> uniform(-1., 1.);
    std::vector<SyntheticPoint<dim>>       points(n_points);
    n_plastic = 0;
    for (SyntheticPoint<dim> &point : points)
      {
        for (unsigned int v = 0; v < n_nodes; ++v)
          for (unsigned int d = 0; d < dim; ++d)
            point.gradients[v][d] = uniform(random);
        Tensor<2, 3> Fn = unit_symmetric_tensor<3>();
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            Fn[i][j] += strain * uniform(random);
        Tensor<2, dim> dF = unit_symmetric_tensor<dim>();
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            dF[i][j] += 0.2 * strain * uniform(random);
        point.dF_inverse = invert(dF);
        material.update(PulledBackStress<dim>::embed(dF),
                        symmetrize(Fn * transpose(Fn)),
                        point.update);
        n_plastic += point.update.plastic;
        point.tangent = PreviouslyConvergedForm<dim>::tangent(material,
                                                              point.update,
                                                              point.dF_inverse,
                                                              1.);
      }
    return points;
  }



  template <int dim>
  void
  run(const unsigned int nodes_per_direction_low,
      const unsigned int nodes_per_direction_high,
      const Material    &material,
      const double       strain,
      const std::string &state,
      const unsigned int n_points,
      const unsigned int trials,
      std::mt19937      &random,
      std::string       &form_table,
      std::string       &kernel_table)
  {
    // Support: nodes_per_direction_low in the first direction,
    // nodes_per_direction_high in the others.
    unsigned int n_nodes = nodes_per_direction_low;
    for (unsigned int d = 1; d < dim; ++d)
      n_nodes *= nodes_per_direction_high;
    const unsigned int n = n_nodes * dim;

    unsigned int                     n_plastic = 0;
    std::vector<SyntheticPoint<dim>> points =
      make_points<dim>(n_nodes, material, strain, n_points, random, n_plastic);

    std::vector<double>        forces(n), matrix(n * n);
    std::vector<unsigned char> rows_needed(n, 1);
    double                     checksum = 0.;
    const auto            stiffness = std::make_unique<PointStiffness<dim>>();
    const TangentSymmetry symmetry  = material.has_symmetric_tangent() ?
                                        TangentSymmetry::major :
                                        TangentSymmetry::general;
    stiffness->reset(n_nodes, symmetry);

    const auto pc_residual = [&](const unsigned int p) {
      const SyntheticPoint<dim> &point = points[p];
      std::fill(forces.begin(), forces.end(), 0.);
      add_point_forces(PreviouslyConvergedForm<dim>::force_stress(
                         point.update, point.dF_inverse, 1.),
                       point.gradients.data(),
                       n_nodes,
                       forces.data());
      checksum += forces[p % n];
    };
    const auto ul_residual = [&](const unsigned int p) {
      SyntheticPoint<dim> &point = points[p];
      UpdatedLagrangianForm<dim>::map_gradients(point.gradients.data(),
                                                n_nodes,
                                                point.dF_inverse,
                                                point.mapped_gradients.data());
      std::fill(forces.begin(), forces.end(), 0.);
      add_point_forces(UpdatedLagrangianForm<dim>::force_stress(
                         point.update, point.dF_inverse, 1.),
                       point.mapped_gradients.data(),
                       n_nodes,
                       forces.data());
      checksum += forces[p % n];
    };
    const auto pc_stiffness = [&](const unsigned int p) {
      const SyntheticPoint<dim> &point = points[p];
      stiffness->add(PreviouslyConvergedForm<dim>::tangent(
                       material, point.update, point.dF_inverse, 1.),
                     point.gradients.data(),
                     rows_needed.data());
    };
    const auto ul_stiffness = [&](const unsigned int p) {
      const SyntheticPoint<dim> &point = points[p];
      stiffness->add(UpdatedLagrangianForm<dim>::tangent(
                       material, point.update, point.dF_inverse, 1.),
                     point.mapped_gradients.data(),
                     rows_needed.data());
    };
    const auto pc_stiffness_before = [&](const unsigned int p) {
      const SyntheticPoint<dim> &point = points[p];
      add_point_stiffness_before(
        PreviouslyConvergedForm<dim>::tangent(
          material, point.update, point.dF_inverse, 1.),
        point.gradients.data(),
        n_nodes,
        matrix.data());
    };
    const auto kernel_before = [&](const unsigned int p) {
      add_point_stiffness_before(points[p].tangent,
                                 points[p].gradients.data(),
                                 n_nodes,
                                 matrix.data());
    };
    const auto general_stiffness = std::make_unique<PointStiffness<dim>>();
    general_stiffness->reset(n_nodes, TangentSymmetry::general);
    const auto kernel_general = [&](const unsigned int p) {
      general_stiffness->add(points[p].tangent,
                             points[p].gradients.data(),
                             rows_needed.data());
    };
    const auto symmetric_stiffness = std::make_unique<PointStiffness<dim>>();
    symmetric_stiffness->reset(n_nodes, TangentSymmetry::major);
    const auto kernel_symmetric = [&](const unsigned int p) {
      symmetric_stiffness->add(points[p].tangent,
                               points[p].gradients.data(),
                               rows_needed.data());
    };
    const std::vector<double> ns = time_per_point(n_points,
                                                  trials,
                                                  {pc_residual,
                                                   ul_residual,
                                                   pc_stiffness,
                                                   ul_stiffness,
                                                   pc_stiffness_before,
                                                   kernel_before,
                                                   kernel_general,
                                                   kernel_symmetric});

    // The same sum over the points by each kernel: the after-matrices
    // against the before-matrix.
    std::fill(matrix.begin(), matrix.end(), 0.);
    general_stiffness->reset(n_nodes, TangentSymmetry::general);
    symmetric_stiffness->reset(n_nodes, TangentSymmetry::major);
    for (unsigned int p = 0; p < n_points; ++p)
      {
        kernel_before(p);
        kernel_general(p);
        kernel_symmetric(p);
      }
    double largest = 0., difference = 0.;
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = 0; b < n; ++b)
        {
          const double before = matrix[a * n + b];
          largest             = std::max(largest, std::abs(before));
          difference =
            std::max({difference,
                      std::abs(general_stiffness->entry(a, b) - before),
                      symmetry == TangentSymmetry::major ?
                        std::abs(symmetric_stiffness->entry(a, b) - before) :
                        0.});
        }
    checksum += stiffness->entry(1, n - 1);

    append_rows(dim,
                n_nodes,
                state,
                100 * n_plastic / n_points,
                ns,
                std::isfinite(checksum),
                symmetry == TangentSymmetry::major,
                difference / largest,
                form_table,
                kernel_table);
  }
} // namespace

int
main(int argc, char **argv)
{
  const unsigned int n_points = argc > 1 ? std::stoi(argv[1]) : 4096;
  const unsigned int trials   = argc > 2 ? std::stoi(argv[2]) : 21;
  std::mt19937       random(2026);

  const HenckyVonMises elastic(1e6,
                               0.3,
                               std::numeric_limits<double>::infinity());
  const HenckyVonMises plastic(1e6, 0.3, 2e4);

  std::printf("Per-point cost (ns, median of %u trials over %u points) of the "
              "previously converged (PC) and updated Lagrangian (UL) forms\n\n",
              trials,
              n_points);
  std::string form_table, kernel_table;
  // Supports of low x high (x high) nodes, each with an elastic and a
  // plastic state, in 2D and then in 3D.
  const auto run_all = [&](auto dimension) {
    constexpr int dim = decltype(dimension)::value;
    for (const auto &[low, high] :
         std::vector<std::pair<unsigned int, unsigned int>>{{2, 2},
                                                            {2, 3},
                                                            {3, 3}})
      for (const auto &[material, strain, state] :
           {std::tuple<const Material &, double, const char *>{elastic,
                                                               0.02,
                                                               "elastic"},
            {plastic, 0.2, "plastic"}})
        run<dim>(low,
                 high,
                 material,
                 strain,
                 state,
                 n_points,
                 trials,
                 random,
                 form_table,
                 kernel_table);
  };
  run_all(std::integral_constant<int, 2>());
  run_all(std::integral_constant<int, 3>());
  std::printf("| dim | support nodes | state | PC residual | UL residual | "
              "PC stiffness | UL stiffness | UL/PC per iteration |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n%s\n", form_table.c_str());
  std::printf("The point stiffness kernel, before and after (ns per point; "
              "\"kernel\" on stored tangents, \"with tangent\" including the "
              "previously converged tangent's evaluation)\n\n");
  std::printf("| dim | support nodes | state | kernel before | after, all "
              "entries | after, symmetric | kernel before/after | with tangent "
              "before | with tangent after | before/after | largest "
              "difference |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n%s",
              kernel_table.c_str());
}
