#ifndef impm_mechanics_point_stiffness_h
#define impm_mechanics_point_stiffness_h

#include <deal.II/base/tensor.h>

#include <impm/basis/basis_functions.h>
#include <impm/mechanics/pulled_back_stress.h>

#include <array>
#include <utility>

namespace impm
{
  using namespace dealii;

  /**
   * @brief What the point stiffness kernel may assume of the tangent
   * @f$A_{ijkq}@f$.
   */
  enum class TangentSymmetry
  {
    /** No symmetry: every entry of the point stiffness is computed. */
    general,
    /**
     * Major symmetry, @f$A_{ijkq} = A_{kqij}@f$ (a model whose stress
     * update derives from a potential, Material::has_symmetric_tangent()):
     * the point stiffness is symmetric and only its node blocks on and
     * above the diagonal are computed.
     */
    major
  };

  /**
   * @brief The dense stiffness of the material points that share one
   * support: @f$K_{(v,i)(w,k)} = \sum_p \nabla S_{v,j} A^p_{ijkq}
   * \nabla S_{w,q}@f$, accumulated point by point.
   *
   * The matrix is stored component-major, DoF (node v, component i) at
   * position @f$i\,n_{nodes} + v@f$, so that the innermost loop of the
   * kernel runs over contiguous nodes with the gradients stored by
   * component (a loop the compiler vectorises, marked `omp simd`). With
   * TangentSymmetry::major only the entries whose column node is not below
   * the row node are written; entry() reads the others from their mirror.
   *
   * The flops per point are @f$n_{nodes} d^4@f$ (the first contraction)
   * plus @f$n_{nodes}^2 d^3@f$ (general) or
   * @f$n_{nodes}(n_{nodes}+1) d^3 / 2@f$ (major symmetry).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class PointStiffness
  {
  public:
    /** Largest number of DoFs of a support. */
    static constexpr unsigned int max_dofs = PointSupport<dim>::max_nodes * dim;

    /**
     * @brief Start a matrix for supports of @p n_nodes nodes: all entries
     * zero.
     */
    void
    reset(const unsigned int n_nodes, const TangentSymmetry symmetry)
    {
      this->n_nodes        = n_nodes;
      this->symmetry       = symmetry;
      const unsigned int n = n_nodes * dim;
      std::fill(values.begin(), values.begin() + n * n, 0.);
    }

    /**
     * @brief Add one point's stiffness with tangent @p A and basis
     * gradients @p gradients (one per node). Rows whose @p rows_needed
     * entry is zero (indexed node * dim + component, as PointStep::dofs)
     * are skipped: their DoFs are not in the linear system, so neither
     * their rows nor their columns are read.
     */
    void
    add(const Tensor<4, dim> &A,
        const Tensor<1, dim> *gradients,
        const unsigned char  *rows_needed)
    {
      constexpr unsigned int max_nodes = PointSupport<dim>::max_nodes;
      const unsigned int     n         = n_nodes * dim;
      // The gradients by component, contiguous over nodes.
      double g[dim][max_nodes];
      for (unsigned int w = 0; w < n_nodes; ++w)
        for (unsigned int q = 0; q < dim; ++q)
          g[q][w] = gradients[w][q];

      for (unsigned int v = 0; v < n_nodes; ++v)
        {
          // A node without gradient (one that the point's support lacks,
          // in a group's larger support) adds nothing to its rows.
          bool zero_gradient = true;
          for (unsigned int j = 0; j < dim; ++j)
            zero_gradient = zero_gradient && g[j][v] == 0.;
          if (zero_gradient)
            continue;
          // B[i][k][q] = grad_v[j] A[i][j][k][q]
          double B[dim][dim][dim] = {};
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              for (unsigned int k = 0; k < dim; ++k)
                for (unsigned int q = 0; q < dim; ++q)
                  B[i][k][q] += g[j][v] * A[i][j][k][q];
          const unsigned int first_column_node =
            symmetry == TangentSymmetry::major ? v : 0;
          for (unsigned int i = 0; i < dim; ++i)
            {
              if (!rows_needed[v * dim + i])
                continue;
              double *row = values.data() + (i * n_nodes + v) * n;
              for (unsigned int k = 0; k < dim; ++k)
                {
                  double *block = row + k * n_nodes;
                  if constexpr (dim == 2)
                    {
                      const double b0 = B[i][k][0], b1 = B[i][k][1];
#pragma omp simd
                      for (unsigned int w = first_column_node; w < n_nodes; ++w)
                        block[w] += b0 * g[0][w] + b1 * g[1][w];
                    }
                  else
                    {
                      const double b0 = B[i][k][0], b1 = B[i][k][1],
                                   b2 = B[i][k][2];
#pragma omp simd
                      for (unsigned int w = first_column_node; w < n_nodes; ++w)
                        block[w] += b0 * g[0][w] + b1 * g[1][w] + b2 * g[2][w];
                    }
                }
            }
        }
    }

    /**
     * @brief Axisymmetry: add one point's hoop terms,
     * @f$K_{(v,i)(w,k)} \mathrel{+}= \nabla S_{v,j} A_{ij\theta\theta}
     * \bar S_w \delta_{k r} + \delta_{i r} \bar S_v A_{\theta\theta kq}
     * \nabla S_{w,q} + \delta_{i r}\delta_{k r} \bar S_v
     * A_{\theta\theta\theta\theta} \bar S_w@f$ with @f$\bar S_v = S_v
     * / r^n@f$ (@p weights_over_radius), the radius being the first
     * component. Only for a matrix started with TangentSymmetry::general.
     */
    void
    add_hoop(const HoopTangent<dim> &hoop,
             const double           *weights_over_radius,
             const Tensor<1, dim>   *gradients,
             const unsigned char    *rows_needed)
    {
      Assert(symmetry == TangentSymmetry::general, ExcInternalError());
      const unsigned int n = n_nodes * dim;
      const double      *h = weights_over_radius;
      for (unsigned int v = 0; v < n_nodes; ++v)
        for (unsigned int i = 0; i < dim; ++i)
          {
            if (!rows_needed[v * dim + i])
              continue;
            double *row = values.data() + (i * n_nodes + v) * n;
            // The in-plane row's change with the hoop stretch (radial
            // columns only).
            const double by_hoop = gradients[v] * hoop.in_plane_by_hoop[i];
            for (unsigned int w = 0; w < n_nodes; ++w)
              row[w] += by_hoop * h[w];
            if (i != 0 || h[v] == 0.)
              continue;
            // The radial row's hoop force.
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int w = 0; w < n_nodes; ++w)
                row[k * n_nodes + w] +=
                  h[v] * (hoop.hoop_by_in_plane[k] * gradients[w]);
            for (unsigned int w = 0; w < n_nodes; ++w)
              row[w] += h[v] * hoop.hoop_by_hoop * h[w];
          }
    }

    /**
     * @brief Store every entry: with TangentSymmetry::major, copy the node
     * blocks below the diagonal from their mirrors, so that data() holds
     * the whole matrix (call after the last add()).
     */
    void
    complete()
    {
      if (symmetry != TangentSymmetry::major)
        return;
      const unsigned int n = n_nodes * dim;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int v = 0; v < n_nodes; ++v)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int w = 0; w < v; ++w)
              values[(i * n_nodes + v) * n + k * n_nodes + w] =
                values[(k * n_nodes + w) * n + i * n_nodes + v];
      symmetry = TangentSymmetry::general;
    }

    /**
     * @brief Where the row of DoF @p a (indexed node * dim + component, as
     * PointStep::dofs) starts in data().
     */
    unsigned int
    row_offset(const unsigned int a) const
    {
      return ((a % dim) * n_nodes + a / dim) * n_nodes * dim;
    }

    /**
     * @brief The offset of the column of DoF @p b (indexed as in
     * row_offset()) from a row's start in data().
     */
    unsigned int
    column_offset(const unsigned int b) const
    {
      return (b % dim) * n_nodes + b / dim;
    }

    /**
     * @brief The entries, component-major; every one only after complete().
     */
    const double *
    data() const
    {
      return values.data();
    }

    /**
     * @brief The entry in row @p a and column @p b, both indexed
     * node * dim + component (as PointStep::dofs).
     */
    double
    entry(const unsigned int a, const unsigned int b) const
    {
      unsigned int row_node = a / dim, column_node = b / dim;
      unsigned int row_component = a % dim, column_component = b % dim;
      if (symmetry == TangentSymmetry::major && column_node < row_node)
        {
          std::swap(row_node, column_node);
          std::swap(row_component, column_component);
        }
      return values[(row_component * n_nodes + row_node) * n_nodes * dim +
                    column_component * n_nodes + column_node];
    }

  private:
    /** Nodes of the current support. */
    unsigned int n_nodes = 0;
    /** What the current matrix assumes of its tangents. */
    TangentSymmetry symmetry = TangentSymmetry::general;
    /** The entries, component-major (see the class description). */
    std::array<double, max_dofs * max_dofs> values;
  };
} // namespace impm

#endif
