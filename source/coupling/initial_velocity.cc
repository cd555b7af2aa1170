// The points' initial velocity of a scene with inertia.
#include <deal.II/base/exceptions.h>

#include <impm/base/errors.h>
#include <impm/coupling/initial_velocity.h>

namespace impm
{
  template <int dim>
  void
  InitialVelocity<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Initial velocity",
                      "0",
                      Patterns::Anything(),
                      "The points' velocity at the start, in m/s: 0, or "
                      "one expression per axis separated by ';' in the "
                      "initial position x, y (and z) and the constant "
                      "pi (deal.II's FunctionParser, muparser syntax), "
                      "e.g. '0.1*sin(pi*x/50); 0'.");
  }



  template <int dim>
  InitialVelocity<dim>::InitialVelocity(const ParameterHandler &prm)
    : expression(prm.get("Initial velocity"))
  {
    if (expression == "0")
      return;
    function = std::make_unique<FunctionParser<dim>>(dim);
    try
      {
        function->initialize(dim == 2 ? "x,y" : "x,y,z",
                             expression,
                             {{"pi", numbers::PI}});
      }
    catch (const ExceptionBase &)
      {
        throw InputError(
          "Parameter 'Inertia/Initial velocity' = '" + expression +
          "' is not allowed: it must "
          "be 0 or " +
          std::to_string(dim) + " expressions in " +
          (dim == 2 ? "x, y" : "x, y, z") + " separated by ';'.");
      }
  }



  template <int dim>
  void
  InitialVelocity<dim>::initialize(MaterialPoints<dim> &material_points,
                                   const bool           gradient) const
  {
    if (!function)
      return;
    material_points.initialize_coupling_field(
      "velocity",
      [this](const PointState<dim> &state, const ArrayView<double> &v) {
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = function->value(state.initial_position(), d);
      });
    if (gradient)
      material_points.initialize_coupling_field(
        "velocity_gradient",
        [this](const PointState<dim> &state, const ArrayView<double> &g) {
          for (unsigned int i = 0; i < dim; ++i)
            {
              const Tensor<1, dim> row =
                function->gradient(state.initial_position(), i);
              for (unsigned int j = 0; j < dim; ++j)
                g[i * dim + j] = row[j];
            }
        });
  }



  template <int dim>
  std::string
  InitialVelocity<dim>::description() const
  {
    return "initial velocity " + expression;
  }



  template class InitialVelocity<2>;
  template class InitialVelocity<3>;
} // namespace impm
