#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/contact/rigid_contact.h>
#include <impm/core/rigid_body.h>
#include <impm/io/atomic_file.h>
#include <impm/io/point_output.h>
#include <impm/postprocess/postprocessor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <string>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * @brief The points as VTU files with a .pvd series ('Output/Interval'
     * > 0): at the start, every 'Interval' converged steps and at full
     * load, with the 'Output/Fields' the scene asks for among those its
     * points have.
     */
    template <int dim>
    class PointFiles : public Postprocessor<dim>
    {
    public:
      /** @brief Files in the scene's output directory. */
      explicit PointFiles(const RunContext<dim> &context)
        : output(context.parameters.scene.output_directory,
                 "points",
                 context.output.format,
                 context.output.compression,
                 context.communicator)
      {
        const auto &fields = context.output.fields;
        const auto &layout = context.material_points.layout();
        body = fields.body && layout.body_index() != PointLayout::absent;
        if (fields.body && !body && !fields.all_declared)
          throw InputError("Output/Fields names 'body', which a scene of one "
                           "body does not store (its points are all of "
                           "Body 1).");
        check_declared_names(fields.declared, layout);
        for (const auto &field : layout.written_fields())
          if (fields.all_declared ||
              std::find(fields.declared.begin(),
                        fields.declared.end(),
                        field.name) != fields.declared.end())
            declared_fields.push_back(field);
        for (unsigned int d = 0; d < dim && fields.displacement; ++d)
          add("displacement", true);
        for (unsigned int d = 0; d < dim && fields.initial_position; ++d)
          add("initial_position", true);
        for (unsigned int i = 0; i < 3 && fields.stress; ++i)
          for (unsigned int j = i; j < 3; ++j)
            add(std::string("stress_") + Names::axis(i) + Names::axis(j),
                false);
        if (fields.von_mises_stress)
          add("von_mises_stress", false);
        for (const auto &field : declared_fields)
          for (unsigned int k = 0; k < field.n_components; ++k)
            add(field.n_components == 1 ? field.name :
                                          field.name + "_" + std::to_string(k),
                false);
        if (fields.volume)
          add("volume", false);
        if (fields.rank)
          add("rank", false);
        if (body)
          add("body", false);
        if (context.couplings.template find<RigidContact<dim>>() != nullptr)
          output.other_parts =
            [this,
             directory = context.parameters.scene.output_directory,
             contact   = context.couplings.template find<RigidContact<dim>>()](
              const std::string &suffix) {
              return write_rigid_bodies(directory, *contact, suffix);
            };
      }

      void
      start(const RunContext<dim> &context) override
      {
        write(context, 0., 0);
      }

      void
      resume(const RunContext<dim> &, const RunState &state) override
      {
        // A checkpoint of a run without point files ('Output/Interval' may
        // change on a resume) holds no series: it starts now.
        if (("\n" + state.to_text()).find("\npoint files.times = ") !=
            std::string::npos)
          output.load(state, "point files");
      }

      void
      save(const RunContext<dim> &, RunState &state) const override
      {
        output.save(state, "point files");
      }

      void
      after_step(const RunContext<dim> &context,
                 const StepRecord      &record,
                 const RunStatistics<dim> &) override
      {
        const unsigned int interval = context.output.interval;
        if (record.converged())
          last_converged_step = record.step_number;
        if (record.converged() &&
            (record.step_number % interval == 0 || record.last))
          write(context, record.target, record.step_number);
      }

      /** The last converged state, unless it was written already. */
      void
      after_failure(const RunContext<dim> &context,
                    const double           converged_load_factor) override
      {
        if (last_converged_step != last_written_step)
          write(context, converged_load_factor, last_converged_step);
      }

    private:
      /**
       * Refuse a name in `Output/Fields` that is neither a built-in field
       * nor one that the scene's points store (one line listing those).
       */
      static void
      check_declared_names(const std::vector<std::string> &names,
                           const PointLayout              &layout)
      {
        for (const auto &name : names)
          {
            bool known = false;
            for (const auto &field : layout.written_fields())
              known = known || field.name == name;
            if (known)
              continue;
            std::string stored;
            for (const auto &field : layout.written_fields())
              stored += ", " + field.name;
            throw InputError(
              "Output/Fields names '" + name +
              "', which this scene's points do not store; its fields are "
              "displacement, initial_position, stress, von_mises_stress, "
              "volume, rank" +
              (layout.body_index() == PointLayout::absent ? "" : ", body") +
              stored + ".");
          }
      }

      /**
       * Write each rigid body's surface at the load factor of the current
       * output as `rigid_k<suffix>.vtu` (polygons, ASCII); return the file
       * names.
       */
      std::vector<std::string>
      write_rigid_bodies(const std::string       &directory,
                         const RigidContact<dim> &contact,
                         const std::string       &suffix) const
      {
        std::vector<std::string> files;
        const auto              &bodies = contact.bodies();
        for (unsigned int k = 0; k < bodies.size(); ++k)
          {
            const auto surface =
              bodies[k].surface(contact.displacement_of(k, load_factor),
                                load_factor);
            const std::string file =
              "rigid_" + std::to_string(k + 1) + suffix + ".vtu";
            write_file_atomically(directory + "/" + file,
                                  [&](std::ostream &out) {
                                    write_surface(surface, out);
                                  });
            files.push_back(file);
          }
        return files;
      }

      /** Write @p surface as a VTU file of polygons (2D) or quadrilaterals
       *  (3D). */
      static void
      write_surface(const typename RigidBody<dim>::Surface &surface,
                    std::ostream                           &out)
      {
        out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
               "version=\"0.1\" byte_order=\"LittleEndian\">\n"
            << "<UnstructuredGrid>\n<Piece NumberOfPoints=\""
            << surface.vertices.size() << "\" NumberOfCells=\""
            << surface.faces.size() << "\">\n<Points>\n<DataArray "
            << "type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
            << std::setprecision(12);
        for (const auto &vertex : surface.vertices)
          {
            for (unsigned int d = 0; d < 3; ++d)
              out << (d < dim ? vertex[d] : 0.) << ' ';
            out << '\n';
          }
        out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" "
               "Name=\"connectivity\" format=\"ascii\">\n";
        for (const auto &face : surface.faces)
          for (const unsigned int v : face)
            out << v << ' ';
        out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
               "format=\"ascii\">\n";
        std::size_t offset = 0;
        for (const auto &face : surface.faces)
          out << (offset += face.size()) << ' ';
        out << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
               "format=\"ascii\">\n";
        for (const auto &face : surface.faces)
          out << (face.size() == 4 && dim == 3 ? 9 : 7) << ' ';
        out << "\n</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n"
               "</VTKFile>\n";
      }

      /** Add the output column @p name (a vector component if @p vector). */
      void
      add(const std::string &name, const bool vector)
      {
        names.push_back(name);
        is_vector.push_back(vector);
      }

      /** Write the points at load factor @p load_factor. */
      void
      write(const RunContext<dim> &context,
            const double           load_factor,
            const unsigned int     load_step)
      {
        TimerOutput::Scope scope(context.timer, "output");
        this->load_factor   = load_factor;
        last_written_step   = load_step;
        const auto  &fields = context.output.fields;
        const auto  &points = context.material_points;
        const double this_rank =
          Utilities::MPI::this_mpi_process(context.communicator);
        output.begin(points.n_local_points(), names, is_vector);
        std::vector<double> values(names.size());
        unsigned int        p = 0;
        for (const auto &point : points.particles())
          {
            const PointState<dim>       state(point.get_properties());
            const Point<dim>            X     = state.initial_position();
            const double                J     = state.jacobian();
            const SymmetricTensor<2, 3> sigma = state.kirchhoff_stress() / J;
            unsigned int                c     = 0;
            for (unsigned int d = 0; d < dim && fields.displacement; ++d)
              values[c++] = point.get_location()[d] - X[d];
            for (unsigned int d = 0; d < dim && fields.initial_position; ++d)
              values[c++] = X[d];
            for (unsigned int i = 0; i < 3 && fields.stress; ++i)
              for (unsigned int j = i; j < 3; ++j)
                values[c++] = sigma[i][j];
            if (fields.von_mises_stress)
              {
                const SymmetricTensor<2, 3> s = deviator(sigma);
                values[c++]                   = std::sqrt(1.5 * (s * s));
              }
            const unsigned int body_index =
              points.body_of(point.get_properties());
            for (const auto &field : declared_fields)
              {
                const unsigned int first = field.first_by_body[body_index];
                for (unsigned int k = 0; k < field.n_components; ++k)
                  values[c++] = first == PointLayout::absent ?
                                  0. :
                                  point.get_properties()[first + k];
              }
            if (fields.volume)
              values[c++] = J * state.initial_volume();
            if (fields.rank)
              values[c++] = this_rank;
            if (body)
              values[c++] = body_index + 1;
            output.set_point(p++, point.get_location(), values);
          }
        output.write(load_factor, load_step);
      }

      PointOutput<dim>         output;
      std::vector<std::string> names;
      std::vector<bool>        is_vector;
      /** The declared fields written, in the layout's order. */
      std::vector<PointLayout::WrittenField> declared_fields;
      bool                                   body;
      /** The load factor of the output being written. */
      double load_factor = 0.;
      /** The step of the last converged attempt (0: the start). */
      unsigned int last_converged_step = 0;
      /** The step whose points were written last. */
      unsigned int last_written_step = 0;
    };
  } // namespace
  IMPM_REGISTER_POSTPROCESSOR(PointFiles,
                              "point files",
                              context.output.interval > 0)
} // namespace impm
