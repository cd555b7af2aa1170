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
// Usage: impm-formulation-kernels [points] [trials]

#include <impm/basis/basis_functions.h>
#include <impm/mechanics/equilibrium_forms.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace impm;

namespace
{
  /** The synthetic state of one point. */
  template <int dim>
  struct SyntheticPoint
  {
    std::array<Tensor<1, dim>, PointSupport<dim>::max_nodes> gradients;
    std::array<Tensor<1, dim>, PointSupport<dim>::max_nodes> mapped_gradients;
    Tensor<2, dim>                                           dF_inverse;
    ConstitutiveUpdate                                       update;
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



  template <int dim>
  void
  run(const unsigned int nodes_per_direction_low,
      const unsigned int nodes_per_direction_high,
      const Material    &material,
      const double       strain,
      const std::string &state,
      const unsigned int n_points,
      const unsigned int trials,
      std::mt19937      &random)
  {
    // Support: nodes_per_direction_low in the first direction,
    // nodes_per_direction_high in the others.
    unsigned int n_nodes = nodes_per_direction_low;
    for (unsigned int d = 1; d < dim; ++d)
      n_nodes *= nodes_per_direction_high;
    const unsigned int n = n_nodes * dim;

    std::uniform_real_distribution<double> uniform(-1., 1.);
    std::vector<SyntheticPoint<dim>>       points(n_points);
    unsigned int                           n_plastic = 0;
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
      }

    std::vector<double>        forces(n), matrix(n * n);
    std::vector<unsigned char> rows_needed(n, 1);
    double                     checksum = 0.;

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
      add_point_stiffness(PreviouslyConvergedForm<dim>::tangent(
                            material, point.update, point.dF_inverse, 1.),
                          point.gradients.data(),
                          n_nodes,
                          rows_needed.data(),
                          matrix.data());
    };
    const auto ul_stiffness = [&](const unsigned int p) {
      const SyntheticPoint<dim> &point = points[p];
      add_point_stiffness(UpdatedLagrangianForm<dim>::tangent(
                            material, point.update, point.dF_inverse, 1.),
                          point.mapped_gradients.data(),
                          n_nodes,
                          rows_needed.data(),
                          matrix.data());
    };
    const std::vector<double> ns =
      time_per_point(n_points,
                     trials,
                     {pc_residual, ul_residual, pc_stiffness, ul_stiffness});
    checksum += matrix[n + 1];

    std::printf("| %u | %u | %s (%u%% plastic) | %.0f | %.0f | %.0f | %.0f | "
                "%.3f |%s\n",
                dim,
                n_nodes,
                state.c_str(),
                100 * n_plastic / n_points,
                ns[0],
                ns[1],
                ns[2],
                ns[3],
                (ns[1] + ns[3]) / (ns[0] + ns[2]),
                std::isfinite(checksum) ? "" : " (non-finite checksum)");
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
  std::printf("| dim | support nodes | state | PC residual | UL residual | "
              "PC stiffness | UL stiffness | UL/PC per iteration |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto &[low, high] :
       std::vector<std::pair<unsigned int, unsigned int>>{{2, 2},
                                                          {2, 3},
                                                          {3, 3}})
    {
      run<2>(low, high, elastic, 0.02, "elastic", n_points, trials, random);
      run<2>(low, high, plastic, 0.2, "plastic", n_points, trials, random);
    }
  for (const auto &[low, high] :
       std::vector<std::pair<unsigned int, unsigned int>>{{2, 2},
                                                          {2, 3},
                                                          {3, 3}})
    {
      run<3>(low, high, elastic, 0.02, "elastic", n_points, trials, random);
      run<3>(low, high, plastic, 0.2, "plastic", n_points, trials, random);
    }
}
