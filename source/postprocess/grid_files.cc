#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <impm/base/errors.h>
#include <impm/core/point_properties.h>
#include <impm/io/atomic_file.h>
#include <impm/io/point_output.h>
#include <impm/postprocess/postprocessor.h>
#include <impm/solver/load_step_problem.h>

#include <string>
#include <utility>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * @brief The first component of a nodal vector whose components are
     * equal (the lumped mass) written as one scalar field.
     */
    template <int dim>
    class FirstComponent : public DataPostprocessorScalar<dim>
    {
    public:
      /** @brief The field @p name. */
      explicit FirstComponent(const std::string &name)
        : DataPostprocessorScalar<dim>(name, update_values)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        for (unsigned int q = 0; q < computed_quantities.size(); ++q)
          computed_quantities[q](0) = inputs.solution_values[q](0);
      }
    };



    /**
     * @brief The grid files ('Output/Grid fields' not empty): nodal fields
     * of the converged load steps on which the point files are written
     * (but the start), as the series grid.pvd of grid_NNNNN.pvtu records
     * with one .vtu piece per process. Each is made on the step's grid
     * after the couplings have accepted the step and before the points
     * move: the step's displacement increment, the lumped mass
     * @f$M_I = \sum_p N_{Ip} m_p@f$, the internal and external force, the
     * reaction (internal minus external force on the DoFs a face condition
     * holds) and, with inertia, the velocity @f$\sum_p N_{Ip} m_p v_p /
     * M_I@f$ of the points' accepted velocities. Only the locally owned
     * cells whose every node carries mass are written: the cells the
     * points' supports cover, so that every node with mass is in the files.
     */
    template <int dim>
    class GridFiles : public Postprocessor<dim>
    {
    public:
      /** @brief The fields the scene asks for; velocity only with inertia. */
      explicit GridFiles(const RunContext<dim> &context)
        : fields(context.output.grid_fields)
        , compression(context.output.compression)
        , directory(context.parameters.scene.output_directory)
        , communicator(context.communicator)
        , mass_field("mass")
      {
        const bool inertia =
          context.material_points.layout().coupling_field_entries("velocity") ==
          dim;
        if (fields.velocity && !inertia)
          throw InputError(
            "Output/Grid fields names velocity, which only a scene with "
            "inertia has ('Inertia/Enabled = true').");
        fields.velocity = fields.velocity || (fields.all && inertia);
      }

      void
      resume(const RunContext<dim> &, const RunState &state) override
      {
        // A checkpoint of a run without grid files (Output entries may
        // change on a resume) holds no series: it starts now.
        if (("\n" + state.to_text()).find("\ngrid files.times = ") ==
            std::string::npos)
          return;
        const auto times = state.get_list("grid files.times");
        const auto steps = state.get_list("grid files.steps");
        series.clear();
        for (unsigned int i = 0; i < times.size() && i < steps.size(); ++i)
          series.emplace_back(times[i], static_cast<unsigned int>(steps[i]));
      }

      void
      save(const RunContext<dim> &, RunState &state) const override
      {
        std::vector<double> times, steps;
        for (const auto &[time, step] : series)
          {
            times.push_back(time);
            steps.push_back(step);
          }
        state.set("grid files.times", times);
        state.set("grid files.steps", steps);
      }

      void
      after_convergence(const RunContext<dim>    &context,
                        const StepRecord         &record,
                        const ConvergedStep<dim> &step) override
      {
        if (record.step_number % context.output.interval != 0 && !record.last)
          return;
        TimerOutput::Scope scope(context.timer, "output");
        write(context, record, step);
      }

    private:
      /** The record of step @p step. */
      static std::string
      record_name(const unsigned int step)
      {
        return "grid_" + Utilities::int_to_string(step, 5) + ".pvtu";
      }

      /** A ghosted copy of @p owned (owned entries only) on @p grid. */
      static NodalVector
      ghosted(const BackgroundGrid<dim> &grid, const NodalVector &owned)
      {
        NodalVector vector;
        grid.reinit_vector(vector);
        vector.copy_locally_owned_data_from(owned);
        vector.update_ghost_values();
        return vector;
      }

      /**
       * The lumped mass and, with the velocity, the momentum of the points
       * at the nodes of the step (ghosted; the momentum then divided by
       * the mass where there is mass).
       */
      void
      map_points(const RunContext<dim> &context,
                 const PointSteps<dim> &steps,
                 NodalVector           &mass,
                 NodalVector           &velocity) const
      {
        context.grid.reinit_vector(mass);
        context.grid.reinit_vector(velocity);
        const auto        &points = context.material_points;
        const unsigned int first =
          fields.velocity ? points.layout().coupling_field("velocity") : 0;
        for (const auto &point : points.particles())
          {
            const auto            properties = point.get_properties();
            const PointStep<dim> &s          = steps.of(point);
            const double          m = PointState<dim>(properties).mass();
            for (unsigned int v = 0; v < s.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                {
                  const unsigned int dof = s.dofs[v * dim + i];
                  mass.local_element(dof) += s.support.weights[v] * m;
                  if (fields.velocity)
                    velocity.local_element(dof) +=
                      s.support.weights[v] * m * properties[first + i];
                }
          }
        for (NodalVector *vector : {&mass, &velocity})
          {
            vector->compress(VectorOperation::add);
            vector->update_ghost_values();
          }
        const unsigned int n_local = context.grid.n_local_dofs();
        for (unsigned int i = 0; i < n_local && fields.velocity; ++i)
          velocity.local_element(i) =
            mass.local_element(i) > 0. ?
              velocity.local_element(i) / mass.local_element(i) :
              0.;
      }

      /** Internal minus external force on the owned DoFs a face condition
       *  holds, zero elsewhere (ghosted). */
      static NodalVector
      reaction(const BackgroundGrid<dim> &grid,
               const NodalVector         &internal,
               const NodalVector         &external)
      {
        NodalVector vector;
        grid.reinit_vector(vector);
        const IndexSet &owned = grid.locally_owned_dofs();
        for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
          if (grid.get_constraints().is_constrained(owned.nth_index_in_set(i)))
            vector.local_element(i) =
              internal.local_element(i) - external.local_element(i);
        vector.update_ghost_values();
        return vector;
      }

      /** Which locally owned cells are written (by active cell index): those
       *  whose every DoF carries mass; and their number. */
      static std::pair<std::vector<bool>, unsigned int>
      cells_with_mass(const BackgroundGrid<dim> &grid, const NodalVector &mass)
      {
        std::vector<bool> written(grid.get_triangulation().n_active_cells(),
                                  false);
        unsigned int      n_written = 0;
        std::vector<types::global_dof_index> dofs(
          grid.get_fe().n_dofs_per_cell());
        for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              bool all = true;
              for (const auto dof : dofs)
                all = all && mass(dof) > 0.;
              written[cell->active_cell_index()] = all;
              n_written += all ? 1 : 0;
            }
        return {written, n_written};
      }

      /** Write the fields of the converged step @p record. */
      void
      write(const RunContext<dim>    &context,
            const StepRecord         &record,
            const ConvergedStep<dim> &step)
      {
        const BackgroundGrid<dim> &grid = context.grid;
        NodalVector                mass, velocity;
        map_points(context, step.point_steps, mass, velocity);
        const NodalVector internal = ghosted(grid, step.internal_force);
        const NodalVector external = ghosted(grid, step.external_force);
        const NodalVector reactions =
          reaction(grid, step.internal_force, step.external_force);
        const auto [written, n_written] = cells_with_mass(grid, mass);

        DataOut<dim>          data_out;
        DataOutBase::VtkFlags vtk_flags;
        vtk_flags.compression_level = compression;
        data_out.set_flags(vtk_flags);
        data_out.attach_dof_handler(grid.get_dof_handler());
        const auto add = [&data_out](const NodalVector &vector,
                                     const std::string &name) {
          data_out.add_data_vector(
            vector,
            std::vector<std::string>(dim, name),
            DataOut<dim>::type_dof_data,
            std::vector<
              DataComponentInterpretation::DataComponentInterpretation>(
              dim, DataComponentInterpretation::component_is_part_of_vector));
        };
        if (fields.displacement_increment)
          add(step.increment, "displacement_increment");
        if (fields.mass)
          data_out.add_data_vector(mass, mass_field);
        if (fields.internal_force)
          add(internal, "internal_force");
        if (fields.external_force)
          add(external, "external_force");
        if (fields.reaction)
          add(reactions, "reaction");
        if (fields.velocity)
          add(velocity, "velocity");

        using cell_iterator     = typename DataOut<dim>::cell_iterator;
        const auto next_written = [&written = written](cell_iterator cell) {
          const auto end = cell->get_triangulation().end();
          while (cell != end &&
                 !(cell->is_active() && cell->is_locally_owned() &&
                   written[cell->active_cell_index()]))
            ++cell;
          return cell;
        };
        data_out.set_cell_selection(
          [&next_written](const Triangulation<dim> &triangulation) {
            return next_written(triangulation.begin_active());
          },
          [&next_written](const Triangulation<dim> &,
                          const cell_iterator &cell) {
            return next_written(std::next(cell));
          });
        data_out.build_patches();

        write_vtu_step(data_out,
                       n_written > 0,
                       directory,
                       "grid_" +
                         Utilities::int_to_string(record.step_number, 5),
                       communicator);
        series.emplace_back(record.target, record.step_number);
        run_collectively(communicator, [&]() {
          if (Utilities::MPI::this_mpi_process(communicator) != 0)
            return;
          std::vector<std::pair<double, std::string>> files;
          for (const auto &[time, step] : series)
            files.emplace_back(time, record_name(step));
          write_file_atomically(directory + "/grid.pvd",
                                [&files](std::ostream &out) {
                                  write_pvd_series(out, files);
                                });
        });
      }

      /** The fields written. */
      Parameters::Output::GridFields fields;
      /** The zlib level of the files' data. */
      const DataOutBase::VtkFlags::ZlibCompressionLevel compression;
      const std::string                                 directory;
      const MPI_Comm                                    communicator;
      /** The mass as a scalar field. */
      const FirstComponent<dim> mass_field;
      /** The series: load factor and step number of each record. */
      std::vector<std::pair<double, unsigned int>> series;
    };
  } // namespace
  IMPM_REGISTER_POSTPROCESSOR(GridFiles,
                              "grid files",
                              context.output.grid_fields.any())
} // namespace impm
