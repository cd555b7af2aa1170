// The point history: chosen points followed through the run in one CSV
// file, the first postprocessor that declares parameters of its own.
#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/io/log_file.h>
#include <impm/postprocess/postprocessor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

namespace impm
{
  namespace
  {
    /** @brief @p coordinates as a point, for messages. */
    template <int dim>
    Point<dim>
    as_point(const std::vector<double> &coordinates)
    {
      Point<dim> point;
      for (unsigned int d = 0; d < dim; ++d)
        point[d] = coordinates[d];
      return point;
    }



    /**
     * @brief `point_history.csv`: the points nearest to the initial
     * positions that subsection "Point history" names (`Positions`), one
     * row per point at the start and after every converged load step: the
     * step, the load factor, the point's number in the list and its id,
     * its position, displacement, Cauchy stress, von Mises stress and every
     * field its points' materials and couplings declare as written (0
     * where its material does not store one), the values the point files
     * write at the same step. Rank 0 writes it; a resumed run cuts it back
     * to the checkpoint.
     */
    template <int dim>
    class PointHistory : public Postprocessor<dim>
    {
    public:
      /** @brief Read `Positions` from the subsection entered. */
      explicit PointHistory(const RunContext<dim> &context)
        : positions(Parameters::get_point_list(context.prm,
                                               "Point history",
                                               "Positions",
                                               dim))
        , region_lower(Parameters::get_point_list(context.prm,
                                                  "Point history",
                                                  "Region lower corner",
                                                  dim))
        , region_upper(Parameters::get_point_list(context.prm,
                                                  "Point history",
                                                  "Region upper corner",
                                                  dim))
      {
        if (region_lower.size() > 1 || region_upper.size() > 1 ||
            region_lower.size() != region_upper.size())
          throw InputError(
            "Point history: give 'Region lower corner' and 'Region upper "
            "corner' together, one point each (or neither).");
        for (unsigned int d = 0; d < dim && !region_lower.empty(); ++d)
          if (!(region_lower[0][d] <= region_upper[0][d]))
            throw InputError("Point history: 'Region lower corner' must lie "
                             "below 'Region upper corner' in every "
                             "coordinate.");
        // A position off the grid is a slip (a point is always on it): its
        // nearest point would be some corner of a body, followed silently
        // (as a point load's position, 'Point load/Positions').
        const auto &grid = context.parameters.grid;
        for (const auto &position : positions)
          for (unsigned int d = 0; d < dim; ++d)
            if (position[d] < grid.lower_corner[d] ||
                position[d] > grid.upper_corner[d])
              {
                std::ostringstream message;
                message << "'Point history/Positions': ("
                        << as_point<dim>(position)
                        << ") lies outside the grid [" << grid.lower_corner
                        << "] - [" << grid.upper_corner << "].";
                throw InputError(message.str());
              }
      }

      /** @brief Declare `Positions` in the current subsection. */
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Positions",
          "",
          Patterns::Anything(),
          "Follow the points nearest to these initial positions (x, y; x, "
          "y; ... with one coordinate per axis; smallest id on a tie) "
          "through the run in point_history.csv: at the start and after "
          "each converged load step, their position, displacement, stress "
          "and declared fields. A position must lie on the grid. Empty: no "
          "history.");
        prm.declare_entry(
          "Region lower corner",
          "",
          Patterns::Anything(),
          "Follow also every point whose initial position "
          "lies in the box from this corner (x, y) to "
          "'Region upper corner', after the points of "
          "'Positions', by id (a large box makes a large "
          "file); it must hold a point at the start. Empty: no region.");
        prm.declare_entry("Region upper corner",
                          "",
                          Patterns::Anything(),
                          "The upper corner of that box.");
      }

      /** @brief Whether the entered subsection names positions. */
      static bool
      wanted(ParameterHandler &prm)
      {
        return !prm.get("Positions").empty() ||
               !prm.get("Region lower corner").empty();
      }

      void
      start(const RunContext<dim> &context) override
      {
        choose_points(context);
        if (is_root(context))
          {
            file.open(context.parameters.scene.output_directory +
                      "/point_history.csv");
            write_header(context);
          }
        write_rows(context, 0, 0., context.time.in_time() ? 0. : -1.);
      }

      void
      resume(const RunContext<dim> &context, const RunState &state) override
      {
        choose_points(context);
        if (is_root(context))
          file.reopen(context.parameters.scene.output_directory +
                        "/point_history.csv",
                      static_cast<std::streamoff>(
                        state.get_double("point_history.csv.size")));
      }

      void
      save(const RunContext<dim> &context, RunState &state) const override
      {
        if (is_root(context))
          state.set("point_history.csv.size", static_cast<double>(file.size()));
      }

      void
      after_step(const RunContext<dim> &context,
                 const StepRecord      &record,
                 const RunStatistics<dim> &) override
      {
        if (record.converged())
          write_rows(context,
                     record.step_number,
                     record.target,
                     record.end_time);
      }

    private:
      /** Whether this process writes the file. */
      static bool
      is_root(const RunContext<dim> &context)
      {
        return Utilities::MPI::this_mpi_process(context.communicator) == 0;
      }

      /** The ids of the points nearest to the positions (collective). */
      void
      choose_points(const RunContext<dim> &context)
      {
        ids.clear();
        for (const auto &position : positions)
          {
            // (distance, id) of the nearest local point; the smallest pair
            // over the processes.
            std::pair<double, types::particle_index> best = {
              std::numeric_limits<double>::max(),
              std::numeric_limits<types::particle_index>::max()};
            for (const auto &point : context.material_points.particles())
              {
                const auto X =
                  PointState<dim>(point.get_properties()).initial_position();
                double distance = 0.;
                for (unsigned int d = 0; d < dim; ++d)
                  distance += std::pow(X[d] - position[d], 2);
                best = std::min(best, {distance, point.get_id()});
              }
            const auto all =
              Utilities::MPI::all_gather(context.communicator, best);
            ids.push_back(std::min_element(all.begin(), all.end())->second);
          }
        if (region_lower.empty())
          return;
        // Every point that starts in the region, by id, on all processes.
        std::vector<types::particle_index> local;
        for (const auto &point : context.material_points.particles())
          {
            const auto X =
              PointState<dim>(point.get_properties()).initial_position();
            bool inside = true;
            for (unsigned int d = 0; d < dim; ++d)
              inside = inside && X[d] >= region_lower[0][d] &&
                       X[d] <= region_upper[0][d];
            if (inside)
              local.push_back(point.get_id());
          }
        std::vector<types::particle_index> in_region;
        for (const auto &part :
             Utilities::MPI::all_gather(context.communicator, local))
          in_region.insert(in_region.end(), part.begin(), part.end());
        if (in_region.empty())
          {
            std::ostringstream message;
            message << "'Point history/Region lower corner' and 'Region "
                       "upper corner': the box ["
                    << as_point<dim>(region_lower[0]) << "] - ["
                    << as_point<dim>(region_upper[0])
                    << "] holds no material point at the start.";
            throw InputError(message.str());
          }
        std::sort(in_region.begin(), in_region.end());
        ids.insert(ids.end(), in_region.begin(), in_region.end());
      }

      /** The header line. */
      void
      write_header(const RunContext<dim> &context)
      {
        std::ostream &out = file.stream();
        out << "step,load_factor,";
        if (context.time.in_time())
          out << "time,";
        out << "point,id";
        for (unsigned int d = 0; d < dim; ++d)
          out << ',' << Names::axis(d);
        for (unsigned int d = 0; d < dim; ++d)
          out << ",displacement_" << Names::axis(d);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            out << ",stress_" << Names::axis(i) << Names::axis(j);
        out << ",von_mises_stress";
        for (const auto &field :
             context.material_points.layout().written_fields())
          for (unsigned int k = 0; k < field.n_components; ++k)
            out << ',' << field.name
                << (field.n_components == 1 ? "" : "_" + std::to_string(k));
        out << '\n';
        file.flush();
      }

      /** The values of one local point, in the header's order. */
      std::vector<double>
      values_of(const RunContext<dim>                  &context,
                const Particles::ParticleAccessor<dim> &point) const
      {
        const auto                  properties = point.get_properties();
        const PointState<dim>       state(properties);
        const SymmetricTensor<2, 3> sigma = state.cauchy_stress();
        std::vector<double>         values;
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(point.get_location()[d]);
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(point.get_location()[d] -
                           state.initial_position()[d]);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            values.push_back(sigma[i][j]);
        const SymmetricTensor<2, 3> s = deviator(sigma);
        values.push_back(std::sqrt(1.5 * (s * s)));
        const unsigned int body = context.material_points.body_of(properties);
        for (const auto &field :
             context.material_points.layout().written_fields())
          for (unsigned int k = 0; k < field.n_components; ++k)
            values.push_back(field.first_by_body[body] == PointLayout::absent ?
                               0. :
                               properties[field.first_by_body[body] + k]);
        return values;
      }

      /** One row per followed point (collective; rank 0 writes). */
      void
      write_rows(const RunContext<dim> &context,
                 const unsigned int     step,
                 const double           load_factor,
                 const double           end_time)
      {
        std::vector<
          std::tuple<unsigned int, types::particle_index, std::vector<double>>>
          local;
        // Each followed id with its numbers in the list (a point may be
        // both nearest to a position and in the region), sorted by id.
        std::vector<std::pair<types::particle_index, unsigned int>> numbers;
        for (unsigned int k = 0; k < ids.size(); ++k)
          numbers.emplace_back(ids[k], k);
        std::sort(numbers.begin(), numbers.end());
        for (const auto &point : context.material_points.particles())
          for (auto entry =
                 std::lower_bound(numbers.begin(),
                                  numbers.end(),
                                  std::make_pair(point.get_id(), 0u));
               entry != numbers.end() && entry->first == point.get_id();
               ++entry)
            local.emplace_back(entry->second,
                               entry->first,
                               values_of(context, point));
        const auto gathered =
          Utilities::MPI::gather(context.communicator, local, 0);
        if (!is_root(context))
          return;
        std::vector<
          std::tuple<unsigned int, types::particle_index, std::vector<double>>>
          rows;
        for (const auto &part : gathered)
          rows.insert(rows.end(), part.begin(), part.end());
        std::sort(rows.begin(), rows.end());
        std::ostream &out = file.stream();
        out << std::setprecision(10);
        for (const auto &[k, id, values] : rows)
          {
            out << step << ',' << load_factor << ',';
            if (end_time >= 0.)
              out << end_time << ',';
            out << k + 1 << ',' << id;
            for (const double value : values)
              out << ',' << value;
            out << '\n';
          }
        file.flush();
      }

      /** The initial positions named. */
      const std::vector<std::vector<double>> positions;
      /** The corners of the region whose points are followed (empty:
       *  none). */
      const std::vector<std::vector<double>> region_lower, region_upper;
      /** The ids of the points followed: one per position, then those of
       *  the region. */
      std::vector<types::particle_index> ids;
      /** point_history.csv (rank 0). */
      LogFile file;
    };
  } // namespace

  IMPM_REGISTER_POSTPROCESSOR_WITH_PARAMETERS(
    PointHistory,
    "Point history",
    PointHistory<dim>::wanted(context.prm),
    ([](ParameterHandler &prm) { PointHistory<dim>::declare_parameters(prm); }))
} // namespace impm
