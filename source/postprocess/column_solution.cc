#include <impm/base/errors.h>
#include <impm/postprocess/column_solution.h>

#include <cmath>

namespace impm
{
  namespace
  {
    /** @brief The column's height l0 and weight per volume rho_0 g. */
    template <int dim>
    std::pair<double, double>
    column_height_and_weight(const RunContext<dim> &context)
    {
      const auto &body = context.parameters.bodies[0];
      return {body.upper_corner[dim - 1] - body.lower_corner[dim - 1],
              body.density * std::abs(context.parameters.gravity[dim - 1])};
    }

    /**
     * @brief Visit every local point of the column with its vertical Cauchy
     * stress, its depth below the column's top in the initial state,
     * l0 - Z, and its initial volume.
     */
    template <int dim, typename Visitor>
    void
    for_each_column_point(const RunContext<dim> &context, Visitor &&visit)
    {
      const auto  &body   = context.parameters.bodies[0];
      const double height = column_height_and_weight(context).first;
      for (const auto &point : context.material_points.particles())
        {
          const PointState<dim> state(point.get_properties());
          const double          Z =
            state.initial_position()[dim - 1] - body.lower_corner[dim - 1];
          visit(state.cauchy_stress()[dim - 1][dim - 1],
                height - Z,
                state.initial_volume());
        }
    }
  } // namespace



  template <int dim>
  std::vector<std::string>
  ColumnSolution<dim>::step_measure_columns() const
  {
    return {"error_sigma_zz"};
  }



  template <int dim>
  void
  ColumnSolution<dim>::measure_step(const RunContext<dim> &context,
                                    StepRecord            &record)
  {
    record.measures.push_back({"error_sigma_zz",
                               "error",
                               error(context, record.target),
                               MeasureKind::number});
  }



  template <int dim>
  double
  ColumnSolution<dim>::error(const RunContext<dim> &context,
                             const double           load_factor)
  {
    const auto [height, weight] = column_height_and_weight(context);
    double local[2]             = {0., 0.};
    for_each_column_point(context,
                          [&, weight = weight](const double sigma,
                                               const double depth,
                                               const double initial_volume) {
                            const double exact = -load_factor * weight * depth;
                            local[0] +=
                              std::abs(sigma - exact) * initial_volume;
                            local[1] += initial_volume;
                          });
    double global[2];
    Utilities::MPI::sum(ArrayView<const double>(local, 2),
                        context.communicator,
                        ArrayView<double>(global, 2));
    return global[0] / (weight * height * global[1]);
  }



  template <int dim>
  double
  ColumnSolution<dim>::max_deviation(const RunContext<dim> &context)
  {
    const auto [height, weight] = column_height_and_weight(context);
    double deviation            = 0.;
    for_each_column_point(context,
                          [&, height = height, weight = weight](
                            const double sigma, const double depth, double) {
                            deviation =
                              std::max(deviation,
                                       std::abs(sigma + weight * depth) /
                                         (weight * height));
                          });
    return Utilities::MPI::max(deviation, context.communicator);
  }



  template <int dim>
  void
  ColumnSolution<dim>::check_scene(const Parameters::All<dim> &parameters)
  {
    const auto &bodies  = parameters.bodies;
    bool        lateral = false;
    for (unsigned int d = 0; d + 1 < dim; ++d)
      lateral = lateral || parameters.gravity[d] != 0.;
    std::string reason;
    if (bodies.size() != 1)
      reason = "the scene has " + std::to_string(bodies.size()) + " bodies";
    else if (bodies[0].shape != Body<dim>::Shape::box)
      reason = "Body 1 is not a box";
    else if (!parameters.gravity_enabled || parameters.gravity[dim - 1] == 0.)
      reason = "no gravity acts along the last axis";
    else if (lateral)
      reason = "gravity acts across the column";
    if (!reason.empty())
      throw InputError("'Output/Analytical solution' = column describes a "
                       "column under its own weight (one box body, gravity "
                       "along the last axis), but " +
                       reason + ": set it to none for this scene.");
  }



  template class ColumnSolution<2>;
  template class ColumnSolution<3>;
  IMPM_REGISTER_POSTPROCESSOR(ColumnSolution,
                              "column solution",
                              context.output.analytical_solution ==
                                impm::Parameters::AnalyticalSolution::column)
} // namespace impm
