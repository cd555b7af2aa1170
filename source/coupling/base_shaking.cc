// Base shaking as a coupling: the inertial load of a rigid base's
// acceleration, read from a time history, in the frame of the base.
#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/coupling/coupling.h>
#include <impm/coupling/fixed_nodal_load.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * @brief A time history of a vector: rows of a time and one value per
     * axis, linearly interpolated, zero after the last row.
     *
     * @tparam dim Space dimension.
     */
    template <int dim>
    class TimeHistory
    {
    public:
      /**
       * @brief Read @p file_name: one row per line, the time in s and then
       * @p dim values, separated by spaces, tabs or commas; empty lines and
       * lines starting with '#' are skipped. A missing file, a row with
       * another number of values or times that do not increase is a
       * one-line InputError naming @p entry.
       */
      TimeHistory(const std::string &file_name, const std::string &entry)
      {
        std::ifstream in(file_name);
        if (!in)
          throw InputError("Parameter '" + entry + "' = '" + file_name +
                           "': the file cannot be read.");
        std::string line;
        for (unsigned int number = 1; std::getline(in, line); ++number)
          {
            std::replace(line.begin(), line.end(), ',', ' ');
            std::istringstream  row(line);
            std::vector<double> values;
            std::string         word;
            while (row >> word)
              {
                if (values.empty() && word[0] == '#')
                  break;
                try
                  {
                    std::size_t  end   = 0;
                    const double value = std::stod(word, &end);
                    if (end != word.size() || !std::isfinite(value))
                      throw std::invalid_argument(word);
                    values.push_back(value);
                  }
                catch (const std::exception &)
                  {
                    throw InputError("Parameter '" + entry + "' = '" +
                                     file_name + "': line " +
                                     std::to_string(number) + " holds '" +
                                     word + "', not a number.");
                  }
              }
            if (values.empty())
              continue;
            if (values.size() != dim + 1)
              throw InputError("Parameter '" + entry + "' = '" + file_name +
                               "': line " + std::to_string(number) + " has " +
                               std::to_string(values.size()) +
                               " numbers; each row needs the time and " +
                               std::to_string(dim) + " components.");
            if (!times.empty() && !(values[0] > times.back()))
              throw InputError("Parameter '" + entry + "' = '" + file_name +
                               "': the times must increase (line " +
                               std::to_string(number) + ").");
            times.push_back(values[0]);
            Tensor<1, dim> value;
            for (unsigned int d = 0; d < dim; ++d)
              value[d] = values[d + 1];
            samples.push_back(value);
          }
        if (times.empty())
          throw InputError("Parameter '" + entry + "' = '" + file_name +
                           "': the file has no rows.");
      }

      /** @brief The value at time @p t: interpolated between the rows,
       *  the first row's before it, zero after the last. */
      Tensor<1, dim>
      value(const double t) const
      {
        if (t > times.back())
          return Tensor<1, dim>();
        if (t <= times.front())
          return samples.front();
        const auto   upper = std::upper_bound(times.begin(), times.end(), t);
        const auto   k     = upper - times.begin();
        const double share = (t - times[k - 1]) / (times[k] - times[k - 1]);
        return (1. - share) * samples[k - 1] + share * samples[k];
      }

      /** @brief The time of the last row. */
      double
      end() const
      {
        return times.back();
      }

      /** @brief Whether a row has a non-zero component @p d. */
      bool
      moves_along(const unsigned int d) const
      {
        for (const auto &sample : samples)
          if (sample[d] != 0.)
            return true;
        return false;
      }

    private:
      std::vector<double>         times;
      std::vector<Tensor<1, dim>> samples;
    };



    /**
     * @brief The shaking of a rigid base: its acceleration @f$a_g(t)@f$
     * from a time history, applied to the material as the inertial load
     * @f$-m\, a_g@f$ of the frame that moves with the base.
     *
     * The displacements, velocities and accelerations of the points are
     * then relative to the base, and the faces that hold the material
     * (the base) move with it. Each step's load is that of its end time,
     * @f$f_I = -M_I\, a_g(t_{n+1})@f$ with the lumped nodal mass of the
     * step's start @f$M_I = \sum_p N_{Ip} m_p@f$, and in the residual of
     * the step's start that of its start time, @f$-M_I\, a_g(t_n)@f$
     * (add_start_forces()): generalised-alpha weighs the two, and the
     * explicit step and the first step's acceleration take the start's.
     * The load does not depend on the displacement: no matrix. A scene that
     * shakes its base needs time and inertia (without inertia the load is a
     * static body force).
     *
     * @tparam dim Space dimension.
     */
    template <int dim>
    class BaseShaking : public Coupling<dim>
    {
    public:
      /** @brief The subsection's entries. */
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Enabled",
                          "false",
                          Patterns::Bool(),
                          "Whether the grid's base is shaken: the material "
                          "is loaded by -m a_g(t) in the base's frame (the "
                          "displacements are relative to the base). Off: "
                          "not created, costs nothing.");
        prm.declare_entry(
          "Acceleration file",
          "",
          Patterns::Anything(),
          "The base's acceleration history: one row per line, the time in "
          "s and one acceleration in m/s^2 per axis, separated by spaces, "
          "tabs or commas ('#' starts a comment line); a relative path is "
          "read from the directory impm runs in. Linear between the rows, "
          "the first row's before it, zero after the last.");
        prm.declare_entry("Scale",
                          "1",
                          Patterns::Double(),
                          "A factor on the file's accelerations (e.g. 9.81 "
                          "for a record in g).");
      }

      /** @brief The shaking of a scene (from its subsection). */
      explicit BaseShaking(const CouplingInputs<dim> &inputs)
        : file_name(inputs.prm.get("Acceleration file"))
        , history(checked_file(file_name, inputs.time),
                  "Base shaking/Acceleration file")
        , scale(inputs.prm.get_double("Scale"))
        , grid(inputs.grid)
      {
        // A rigid base of a body of revolution moves along its axis only.
        if (inputs.parameters.grid.axisymmetric && scale != 0. &&
            history.moves_along(0))
          throw InputError(
            "Parameter 'Base shaking/Acceleration file' = '" + file_name +
            "' has a radial (first) component, which an axisymmetric scene "
            "cannot carry: a rigid base of a body of revolution moves along "
            "its axis only (the second component); shake a 2D or 3D model "
            "sideways.");
      }

      std::vector<std::string>
      descriptions() const override
      {
        std::ostringstream out;
        out << "base shaking: acceleration from " << file_name;
        if (scale != 1.)
          out << " times " << scale;
        out << " (to t = " << history.end() << " s)";
        return {out.str()};
      }

      /** @brief The nodal load of the step's end time. */
      void
      begin_attempt(const MaterialPoints<dim> &material_points,
                    const LoadStepSystem<dim> &system,
                    const StepSpan            &span) override
      {
        acceleration = scale * history.value(span.end_time);
        const Tensor<1, dim> start_acceleration =
          scale * history.value(span.start_time);
        NodalVector &load       = nodal_load.reset(grid);
        NodalVector &start_load = start_nodal_load.reset(grid);
        for (const auto &point : material_points.particles())
          {
            const PointStep<dim> &step = system.point_steps.of(point);
            const double m = PointState<dim>(point.get_properties()).mass();
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                {
                  const unsigned int dof = step.dofs[v * dim + i];
                  load.local_element(dof) -=
                    step.support.weights[v] * m * acceleration[i];
                  start_load.local_element(dof) -=
                    step.support.weights[v] * m * start_acceleration[i];
                }
          }
        nodal_load.finish(system, grid);
        start_nodal_load.finish(system, grid);
      }

      /** @brief Minus the load of the step's start time. */
      void
      add_start_forces(const LoadStepSystem<dim> &,
                       const NodalVector &,
                       NodalVector &internal_force) override
      {
        start_nodal_load.subtract_from(internal_force);
      }

      /** @brief Minus the load, at the owned DoFs of the system (the
       *  internal force is balanced against it). */
      void
      add_forces(const LoadStepSystem<dim> &,
                 const NodalVector &,
                 NodalVector &internal_force) override
      {
        nodal_load.subtract_from(internal_force);
      }

      /** @brief The load's work on the material: the mean of the start
       *  time's and the end time's nodal load (linear in time between
       *  them) times the increment. */
      void
      add_step_energy(const LoadStepSystem<dim> &,
                      const NodalVector &increment,
                      StepEnergy        &energy) override
      {
        energy.external_work +=
          0.5 * (nodal_load.work(increment) + start_nodal_load.work(increment));
      }

      /** @brief The size of the load. */
      double
      reference_force() const override
      {
        return nodal_load.norm();
      }

      /** @brief Minus the load (it enters the balance through the internal
       *  force). */
      Tensor<1, dim>
      force_from_material() const override
      {
        return -nodal_load.sum();
      }

      std::vector<std::string>
      step_measure_columns() const override
      {
        std::vector<std::string> columns;
        for (unsigned int d = 0; d < dim; ++d)
          columns.push_back("base_acceleration_" + Names::axis(d));
        return columns;
      }

      void
      step_measures(const double,
                    std::vector<StepMeasure> &measures) const override
      {
        for (unsigned int d = 0; d < dim; ++d)
          measures.push_back({"base_acceleration_" + Names::axis(d),
                              "ag" + Names::axis(d),
                              acceleration[d],
                              MeasureKind::number});
      }

    private:
      /** @brief @p name, after checking that the scene has time. */
      static const std::string &
      checked_file(const std::string &name, const Parameters::Time &time)
      {
        if (!time.in_time())
          throw InputError("Base shaking needs time: set 'Time/End time' "
                           "above 0 (and enable 'Inertia').");
        if (name.empty())
          throw InputError("Parameter 'Base shaking/Acceleration file' is "
                           "empty: name the base's acceleration history.");
        return name;
      }

      const std::string          file_name;
      const TimeHistory<dim>     history;
      const double               scale;
      const BackgroundGrid<dim> &grid;
      /** The base's acceleration at the step's end. */
      Tensor<1, dim> acceleration;
      /** The nodal load -M a_g of the step's end and of its start. */
      FixedNodalLoad<dim> nodal_load, start_nodal_load;
    };
  } // namespace

  IMPM_REGISTER_COUPLING(BaseShaking,
                         "Base shaking",
                         inputs.prm.get_bool("Enabled"),
                         ([](ParameterHandler &prm) {
                           BaseShaking<dim>::declare_parameters(prm);
                         }))
} // namespace impm
