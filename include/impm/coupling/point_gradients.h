#ifndef impm_coupling_point_gradients_h
#define impm_coupling_point_gradients_h

#include <deal.II/base/tensor.h>

namespace impm
{
  using namespace dealii;

  /**
   * @brief What the statement of equilibrium gives a coupling of each point
   * of the load step (by its index in LoadStepSystem::point_steps): the
   * gradients it assembles with and the map of those to the current
   * configuration. The Assembler implements it.
   */
  template <int dim>
  class PointGradients
  {
  public:
    /** @brief Destructor. */
    virtual ~PointGradients() = default;

    /** @brief The statement's gradients of point @p p, one per node of
     *  its support. */
    virtual const Tensor<1, dim> *
    gradients(const unsigned int p) const = 0;

    /** @brief What maps point @p p's gradients to the current
     *  configuration (@f$\Delta F^{-1}@f$ for start-of-step gradients, the
     *  identity for mapped ones). */
    virtual Tensor<2, dim>
    gradient_map(const unsigned int p) const = 0;

    /** @brief Axisymmetry only: the statement's hoop weights of point
     *  @p p, one per node of its support (the averages of @f$N_v / r^n@f$
     *  for the start-of-step grid, of @f$N_v / r^{n+1}@f$ for the current
     *  configuration). */
    virtual const double *
    hoop_weights(const unsigned int p) const = 0;

    /** @brief Axisymmetry: what maps point @p p's hoop weights to the
     *  current configuration (@f$1/\Delta F_{\theta\theta}@f$ for
     *  start-of-step weights, 1 for mapped ones). */
    virtual double
    hoop_map(const unsigned int p) const = 0;
  };
} // namespace impm

#endif
