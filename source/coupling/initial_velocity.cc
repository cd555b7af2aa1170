// The points' initial velocity of a scene with inertia.
#include <deal.II/base/exceptions.h>

#include <impm/base/errors.h>
#include <impm/base/quiet_call.h>
#include <impm/coupling/initial_velocity.h>

#include <cmath>
#include <sstream>

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
    // A syntax error (an unknown variable such as t, an unclosed bracket)
    // shows at the first evaluation (reported in the one line below).
    if (!quiet_call([&]() {
          function->initialize(dim == 2 ? "x,y" : "x,y,z",
                               expression,
                               {{"pi", numbers::PI}});
          for (unsigned int d = 0; d < dim; ++d)
            (void)function->value(Point<dim>(), d);
        }))
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
    // A value that is not finite (a root of a negative number, a division
    // by zero) is named with the first point it gives it, on every process.
    std::string local_error;
    const auto  check =
      [&](const double value, const Point<dim> &position, const char *what) {
        if (std::isfinite(value) || !local_error.empty())
          return;
        std::ostringstream out;
        out << "Parameter 'Inertia/Initial velocity' = '" << expression
            << "' gives " << what << " that is not finite (" << value
            << ") at the point initially at (" << position
            << "): it must be finite wherever the bodies' points lie.";
        local_error = out.str();
      };
    material_points.initialize_coupling_field(
      "velocity",
      [&](const PointState<dim> &state, const ArrayView<double> &v) {
        for (unsigned int d = 0; d < dim; ++d)
          {
            v[d] = function->value(state.initial_position(), d);
            check(v[d], state.initial_position(), "a velocity");
          }
      });
    if (gradient)
      material_points.initialize_coupling_field(
        "velocity_gradient",
        [&](const PointState<dim> &state, const ArrayView<double> &g) {
          for (unsigned int i = 0; i < dim; ++i)
            {
              const Tensor<1, dim> row =
                function->gradient(state.initial_position(), i);
              for (unsigned int j = 0; j < dim; ++j)
                {
                  g[i * dim + j] = row[j];
                  check(row[j],
                        state.initial_position(),
                        "a velocity gradient (APIC's, by central "
                        "differences)");
                }
            }
        });
    throw_if_any_failed(local_error, material_points.get_communicator(), false);
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
