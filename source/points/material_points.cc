#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/points/material_points.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace impm
{
  template <int dim>
  MaterialPoints<dim>::MaterialPoints(
    const std::vector<Body<dim>> &bodies,
    BackgroundGrid<dim>          &grid,
    const MPI_Comm                communicator,
    const Tensor<1, dim>         &gravity_from_the_start,
    const RunState               *checkpoint_state,
    const PointFields            &coupling_fields)
    : bodies(bodies)
    , grid(grid.cartesian())
    , communicator(communicator)
  {
    std::vector<PointFields> material_fields;
    for (const auto &body : bodies)
      material_fields.push_back(body.material->state_fields());
    property_layout.initialize(PointProperties<dim>::n_fixed_properties,
                               material_fields,
                               coupling_fields);
    // A checkpoint resumes into the layout it was written with only (its
    // particle data would be read wrongly otherwise).
    if (checkpoint_state != nullptr &&
        checkpoint_state->get_string("points.layout") !=
          property_layout.description())
      throw InputError(
        "The checkpoint's material points store " +
        checkpoint_state->get_string("points.layout") + ", this scene's " +
        property_layout.description() +
        ": resume with the scene the checkpoint was written from.");
    // Share the cells by the points they will hold before seeding, so that
    // not all points are seeded on the bodies' processes.
    if (checkpoint_state == nullptr &&
        Utilities::MPI::n_mpi_processes(communicator) > 1)
      grid.partition_by(
        [this](const typename Triangulation<dim>::cell_iterator &cell,
               const typename Triangulation<dim>::CellStatus     status) {
          return status == Triangulation<dim>::CELL_PERSIST ?
                   point_weight * n_seeded_points(cell) :
                   0u;
        });
    particle_handler.initialize(grid.get_triangulation(),
                                grid.get_mapping(),
                                property_layout.n_properties());
    if (checkpoint_state == nullptr)
      {
        seed(grid, gravity_from_the_start);
        return;
      }
    particle_handler.deserialize();
    particle_handler.update_cached_numbers();
    mass_at_creation = checkpoint_state->get_double("points.mass at creation");
    if (static_cast<double>(particle_handler.n_global_particles()) !=
        checkpoint_state->get_double("points.number"))
      throw CollectiveError(
        "The checkpoint's grid holds " +
        std::to_string(particle_handler.n_global_particles()) +
        " material points, its state " +
        std::to_string(
          static_cast<long>(checkpoint_state->get_double("points.number"))) +
        ": the checkpoint is damaged.");
  }



  template <int dim>
  void
  MaterialPoints<dim>::set_coupling_field(const std::string     &name,
                                          const PointSteps<dim> &point_steps,
                                          const std::vector<double> &values)
  {
    const unsigned int first = property_layout.coupling_field(name);
    Assert(first != PointLayout::absent, ExcInternalError());
    AssertDimension(point_steps.size(), n_local_points());
    const std::size_t n =
      values.size() / std::max<std::size_t>(point_steps.size(), 1);
    AssertDimension(values.size(), n * point_steps.size());
    for (auto &point : particle_handler)
      {
        const auto from = values.begin() + point_steps.index_of(point) * n;
        std::copy(from, from + n, point.get_properties().begin() + first);
      }
  }



  template <int dim>
  void
  MaterialPoints<dim>::initialize_coupling_field(
    const std::string                                    &name,
    const std::function<void(const PointState<dim> &,
                             const ArrayView<double> &)> &value)
  {
    const unsigned int first = property_layout.coupling_field(name);
    Assert(first != PointLayout::absent, ExcInternalError());
    const unsigned int n = property_layout.coupling_field_entries(name);
    for (auto &point : particle_handler)
      {
        const auto properties = point.get_properties();
        value(PointState<dim>(
                ArrayView<const double>(properties.data(), properties.size())),
              ArrayView<double>(properties.data() + first, n));
      }
  }



  template <int dim>
  void
  MaterialPoints<dim>::prepare_for_checkpoint()
  {
    particle_handler.prepare_for_serialization();
  }



  template <int dim>
  void
  MaterialPoints<dim>::save(RunState &state) const
  {
    state.set("points.mass at creation", mass_at_creation);
    state.set("points.number",
              static_cast<double>(particle_handler.n_global_particles()));
    state.set("points.layout", property_layout.description());
  }



  template <int dim>
  std::pair<Point<dim>, std::uint64_t>
  MaterialPoints<dim>::cell_origin(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    std::uint64_t cell_index = 0;
    Point<dim>    cell_lower;
    for (int d = dim - 1; d >= 0; --d)
      {
        const unsigned int i = static_cast<unsigned int>(
          std::floor((cell->center()[d] - grid.lower[d]) / grid.cell_size[d]));
        cell_index    = cell_index * grid.n_cells[d] + i;
        cell_lower[d] = grid.node_coordinate(d, i);
      }
    return {cell_lower, cell_index};
  }



  template <int dim>
  Point<dim>
  MaterialPoints<dim>::lattice_position(const Point<dim>  &cell_lower,
                                        const unsigned int n,
                                        const unsigned int q,
                                        Point<dim>        &reference) const
  {
    Point<dim>   position;
    unsigned int rest = q;
    for (unsigned int d = 0; d < dim; ++d)
      {
        reference[d] = (rest % n + 0.5) / n;
        rest /= n;
        position[d] = cell_lower[d] + reference[d] * grid.cell_size[d];
      }
    return position;
  }



  template <int dim>
  unsigned int
  MaterialPoints<dim>::n_seeded_points(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    const Point<dim> cell_lower = cell_origin(cell).first;
    unsigned int     n_points   = 0;
    Point<dim>       reference;
    for (const auto &body : bodies)
      {
        const unsigned int n          = body.points_per_direction;
        const unsigned int n_per_cell = Utilities::pow(n, dim);
        for (unsigned int q = 0; q < n_per_cell; ++q)
          if (body.contains(lattice_position(cell_lower, n, q, reference)))
            ++n_points;
      }
    return n_points;
  }



  template <int dim>
  void
  MaterialPoints<dim>::seed(const BackgroundGrid<dim> &background,
                            const Tensor<1, dim>      &gravity_from_the_start)
  {
    using P = PointProperties<dim>;
    // A geostatic start needs gravity along the last axis, downwards, in
    // full from the first step.
    const double g = -gravity_from_the_start[dim - 1];
    for (const auto &body : bodies)
      if (body.initial_stress.geostatic)
        {
          Tensor<1, dim> lateral = gravity_from_the_start;
          lateral[dim - 1]       = 0.;
          if (!(g > 0.) || lateral.norm() != 0.)
            throw InputError(
              "Parameter '" + body.name +
              "/Initial stress' = 'geostatic' needs gravity along the " +
              (dim == 2 ? "-y" : "-z") +
              " axis acting in full from the first load step: set "
              "Gravity/Enabled = true, Gravity/Ramped = false and a downward "
              "Gravity/Acceleration.");
        }
    std::string outside_yield_surface;

    double cell_volume = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      cell_volume *= grid.cell_size[d];

    std::vector<double> properties(property_layout.n_properties(), 0.);
    for (unsigned int i = 0; i < 3; ++i)
      {
        properties[P::deformation_gradient + 4 * i]  = 1.;
        properties[P::elastic_left_cauchy_green + i] = 1.;
      }

    // Ids from the structured cell index, the body and the position in the
    // cell: the same on any number of processes.
    constexpr unsigned int    max_per_cell = dim == 2 ? 100 : 1000;
    std::vector<unsigned int> points_of_body(bodies.size(), 0);
    std::string               overlap;
    for (const auto &cell :
         background.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto [cell_lower, cell_index] = cell_origin(cell);
          for (unsigned int b = 0; b < bodies.size(); ++b)
            {
              const auto        &body       = bodies[b];
              const unsigned int n          = body.points_per_direction;
              unsigned int       n_per_cell = 1;
              for (unsigned int d = 0; d < dim; ++d)
                n_per_cell *= n;
              const double volume = cell_volume / n_per_cell;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  properties[P::domain_half_length + d] =
                    grid.cell_size[d] / (2. * n);
                  properties[P::initial_domain_half_length + d] =
                    grid.cell_size[d] / (2. * n);
                }
              if (property_layout.body_index() != PointLayout::absent)
                properties[property_layout.body_index()] = b;
              for (unsigned int q = 0; q < n_per_cell; ++q)
                {
                  Point<dim>       reference;
                  const Point<dim> position =
                    lattice_position(cell_lower, n, q, reference);
                  if (!body.contains(position))
                    continue;
                  ++points_of_body[b];
                  for (unsigned int other = 0;
                       other < bodies.size() && overlap.empty();
                       ++other)
                    if (other != b && bodies[other].contains(position))
                      {
                        std::ostringstream message;
                        message << bodies[std::min(b, other)].name << " and "
                                << bodies[std::max(b, other)].name
                                << " overlap (both contain (" << position
                                << ")): bodies may touch but not share "
                                   "volume, or their mass would count twice.";
                        overlap = message.str();
                      }
                  for (unsigned int d = 0; d < dim; ++d)
                    properties[P::initial_position + d] = position[d];
                  properties[P::initial_volume] = // (its ring's)
                    volume * grid.ring_length(position);
                  properties[P::mass] =
                    body.density * properties[P::initial_volume];
                  set_initial_stress(
                    body, position, g, properties, outside_yield_surface);
                  particle_handler.insert_particle(
                    position,
                    reference,
                    (cell_index * Body<dim>::max_bodies + b) * max_per_cell + q,
                    cell,
                    ArrayView<const double>(properties));
                }
            }
        }
    throw_if_any_failed(overlap, communicator);
    if (Utilities::MPI::logical_or(!outside_yield_surface.empty(),
                                   communicator))
      {
        // The message of the lowest process that has one.
        const auto messages =
          Utilities::MPI::all_gather(communicator, outside_yield_surface);
        for (const auto &message : messages)
          if (!message.empty())
            throw InputError(message);
      }
    check_bodies_hold_points(points_of_body);
    particle_handler.update_cached_numbers();
    double mass = 0.;
    for (const auto &point : particle_handler)
      mass += PointState<dim>(point.get_properties()).mass();
    mass_at_creation = Utilities::MPI::sum(mass, communicator);
    if (particle_handler.n_global_particles() == 0)
      throw InputError(
        "The bodies contain no material points: no point position of the "
        "grid's cells lies inside them.");
  }



  namespace
  {
    /** What force effects may know of one point. */
    template <int dim>
    MaterialPointInfo<dim>
    info_of(const Particles::ParticleAccessor<dim> &point,
            const unsigned int                      body)
    {
      const PointState<dim>  state(point.get_properties());
      MaterialPointInfo<dim> info;
      info.id               = point.get_id();
      info.initial_position = state.initial_position();
      info.body             = body;
      info.mass             = state.mass();
      return info;
    }
  } // namespace



  template <int dim>
  std::vector<MaterialPointInfo<dim>>
  MaterialPoints<dim>::infos() const
  {
    std::vector<MaterialPointInfo<dim>> list;
    list.reserve(n_local_points());
    for (const auto &point : particle_handler)
      list.push_back(info_of(point, body_of(point.get_properties())));
    return list;
  }



  template <int dim>
  std::vector<MaterialPointInfo<dim>>
  MaterialPoints<dim>::infos(const PointSteps<dim> &point_steps) const
  {
    AssertDimension(point_steps.size(), n_local_points());
    std::vector<MaterialPointInfo<dim>> list(n_local_points());
    for (const auto &point : particle_handler)
      list[point_steps.index_of(point)] =
        info_of(point, body_of(point.get_properties()));
    return list;
  }



  template <int dim>
  std::vector<double>
  MaterialPoints<dim>::cell_fill_fractions(
    const BackgroundGrid<dim> &background) const
  {
    std::vector<double> fill(background.get_triangulation().n_active_cells(),
                             0.);
    for (const auto &cell :
         background.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double volume = 0.;
          // (In axisymmetry a point's volume is its ring's.)
          for (const auto &point : particle_handler.particles_in_cell(cell))
            volume += PointState<dim>(point.get_properties()).volume() /
                      grid.ring_length(point.get_location());
          fill[cell->active_cell_index()] = volume / cell->measure();
        }
    return fill;
  }



  template <int dim>
  void
  MaterialPoints<dim>::advance(const PointSteps<dim> &point_steps,
                               const NodalVector     &increment,
                               const bool             update_domains,
                               const bool             move_points,
                               const unsigned int     load_step)
  {
    std::string left_grid;
    for (auto &point : particle_handler)
      {
        const PointStep<dim>        &step = point_steps.of(point);
        const MutablePointState<dim> state(point.get_properties());

        const Point<dim> position =
          move_points ? point.get_location() + step.displacement(increment) :
                        point.get_location();

        const Tensor<2, 3> F =
          step.full_deformation_increment() * state.deformation_gradient();
        state.set_deformation_gradient(F);
        state.set_elastic_left_cauchy_green(
          step.update.elastic_left_cauchy_green);
        state.set_kirchhoff_stress(step.update.kirchhoff_stress);
        step.material->store_state(step.update,
                                   material_state(point.get_properties()));

        if (update_domains)
          {
            // lp = lp0 U_ii with U the right stretch tensor of F = R U.
            const SymmetricTensor<2, 3> U =
              symmetrize(transpose(F) * F); // C = U^2
            const auto eigen = spectral_decomposition(U);
            const auto initial_half_length =
              point.get_properties().data() +
              PointProperties<dim>::initial_domain_half_length;
            for (unsigned int d = 0; d < dim; ++d)
              {
                double stretch = 0.;
                for (unsigned int a = 0; a < 3; ++a)
                  stretch += std::sqrt(eigen[a].first) * eigen[a].second[d] *
                             eigen[a].second[d];
                // At most h/2: a domain then spans at most three nodes.
                state.set_domain_half_length(d,
                                             std::min(initial_half_length[d] *
                                                        stretch,
                                                      0.5 * grid.cell_size[d]));
              }
          }
        // In axisymmetry a domain stays off the axis.
        if (grid.axisymmetric && state.domain_half_length()[0] > position[0])
          state.set_domain_half_length(0, position[0]);

        bool finite = true;
        for (unsigned int d = 0; d < dim; ++d)
          finite &= std::isfinite(position[d]);
        if ((!finite || !grid.contains(position)) && left_grid.empty())
          {
            std::ostringstream message;
            message << "Load step " << load_step << ": material point "
                    << point.get_id() << " (initially at "
                    << state.initial_position() << ") moved to (" << position
                    << "), outside the background grid [" << grid.lower
                    << "] - [" << grid.upper << "].";
            left_grid = message.str();
          }
        point.set_location(position);
      }

    const auto messages = Utilities::MPI::all_gather(communicator, left_grid);
    for (const auto &message : messages)
      if (!message.empty())
        throw PointLeftGrid(message);
  }



  template <int dim>
  PointMeasures<dim>
  MaterialPoints<dim>::measure() const
  {
    double     mass = 0., tension = -std::numeric_limits<double>::max();
    Point<dim> initial_min, initial_max, current_min, current_max;
    for (unsigned int d = 0; d < dim; ++d)
      {
        initial_min[d] = current_min[d] = std::numeric_limits<double>::max();
        initial_max[d] = current_max[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &point : particle_handler)
      {
        const PointState<dim> state(point.get_properties());
        mass += state.mass();
        tension = std::max(tension, state.cauchy_stress()[dim - 1][dim - 1]);
        const Point<dim> X = state.initial_position();
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double x = point.get_location()[d];
            initial_min[d] = std::min(initial_min[d], X[d]);
            initial_max[d] = std::max(initial_max[d], X[d]);
            current_min[d] = std::min(current_min[d], x);
            current_max[d] = std::max(current_max[d], x);
          }
      }
    PointMeasures<dim> measures;
    measures.total_mass = Utilities::MPI::sum(mass, communicator);
    measures.max_tensile_vertical_stress =
      Utilities::MPI::max(tension, communicator);
    for (unsigned int d = 0; d < dim; ++d)
      {
        measures.initial_min[d] =
          Utilities::MPI::min(initial_min[d], communicator);
        measures.initial_max[d] =
          Utilities::MPI::max(initial_max[d], communicator);
        measures.current_min[d] =
          Utilities::MPI::min(current_min[d], communicator);
        measures.current_max[d] =
          Utilities::MPI::max(current_max[d], communicator);
      }
    return measures;
  }



  template <int dim>
  double
  MaterialPoints<dim>::imbalance() const
  {
    const double most =
      Utilities::MPI::max(double(n_local_points()), communicator);
    const double mean =
      double(n_global_points()) / Utilities::MPI::n_mpi_processes(communicator);
    return mean > 0. ? most / mean : 1.;
  }



  template <int dim>
  unsigned int
  MaterialPoints<dim>::cell_weight(
    const typename Triangulation<dim>::cell_iterator &cell,
    const typename Triangulation<dim>::CellStatus     status) const
  {
    unsigned int n_points = 0;
    switch (status)
      {
        case Triangulation<dim>::CELL_PERSIST:
        case Triangulation<dim>::CELL_REFINE:
          n_points = particle_handler.n_particles_in_cell(cell);
          break;
        case Triangulation<dim>::CELL_COARSEN:
          for (const auto &child : cell->child_iterators())
            n_points += particle_handler.n_particles_in_cell(child);
          break;
        default:
          break;
      }
    return point_weight * n_points;
  }



  template <int dim>
  void
  MaterialPoints<dim>::prepare_for_repartition()
  {
    particle_handler.prepare_for_coarsening_and_refinement();
  }



  template <int dim>
  void
  MaterialPoints<dim>::unpack_after_repartition()
  {
    const auto n_before = n_global_points();
    particle_handler.unpack_after_coarsening_and_refinement();
    if (particle_handler.n_global_particles() != n_before)
      throw CollectiveError(
        "Material points were lost while repartitioning the grid.");
  }



  template class MaterialPoints<2>;
  template class MaterialPoints<3>;
} // namespace impm
