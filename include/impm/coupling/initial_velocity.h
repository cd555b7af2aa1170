#ifndef impm_coupling_initial_velocity_h
#define impm_coupling_initial_velocity_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <impm/points/material_points.h>

#include <memory>
#include <string>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The points' velocity at the start of a scene with inertia
   * (Inertia's 'Initial velocity'): 0, or one FunctionParser expression
   * per axis in the initial position, written into the points' declared
   * `velocity` field.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class InitialVelocity
  {
  public:
    /** @brief Declare 'Initial velocity' in the current subsection. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** @brief Read it; an expression that does not parse is an
     *  InputError naming it. */
    explicit InitialVelocity(const ParameterHandler &prm);

    /** @brief Whether the scene gives a velocity other than 0. */
    bool
    active() const
    {
      return static_cast<bool>(function);
    }

    /** @brief Set the points' `velocity` field, and with @p gradient
     *  their `velocity_gradient` (APIC) to the expressions' gradient (by
     *  central differences; row-major); nothing if inactive. */
    void
    initialize(MaterialPoints<dim> &material_points, const bool gradient) const;

    /** @brief "initial velocity EXPRESSION". */
    std::string
    description() const;

  private:
    const std::string                    expression;
    std::unique_ptr<FunctionParser<dim>> function;
  };
} // namespace impm

#endif
