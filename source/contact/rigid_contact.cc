#include <deal.II/base/quadrature_lib.h>

#include <impm/base/errors.h>
#include <impm/contact/rigid_contact.h>
#include <impm/core/point_properties.h>
#include <impm/system/load_step_system.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impm
{
  namespace
  {
    /** The force-driven components of @p rigid_bodies, body by body. */
    template <int dim>
    std::vector<typename RigidContact<dim>::Unknown>
    collect_unknowns(const std::vector<RigidBody<dim>> &rigid_bodies)
    {
      std::vector<typename RigidContact<dim>::Unknown> unknowns;
      for (unsigned int b = 0; b < rigid_bodies.size(); ++b)
        for (const unsigned int d : rigid_bodies[b].force_components)
          unknowns.push_back({b, d});
      return unknowns;
    }
  } // namespace



  template <int dim>
  RigidContact<dim>::RigidContact(
    const std::vector<RigidBody<dim>> &rigid_bodies,
    const BackgroundGrid<dim>         &grid)
    : rigid_bodies(rigid_bodies)
    , grid(grid)
    , friction(has_friction(rigid_bodies))
    , probes_per_face(max_face_points(rigid_bodies))
    , n_traction_entries(traction_entries(rigid_bodies))
    , body_unknowns(collect_unknowns(rigid_bodies))
    , displacement(rigid_bodies.size())
    , start_displacement(rigid_bodies.size())
    , displacement_increment(rigid_bodies.size())
    , rotation(rigid_bodies.size())
    , start_rotation(rigid_bodies.size())
    , rotation_increment(rigid_bodies.size())
    , accepted_unknowns(rigid_bodies.size())
    , applied_force(rigid_bodies.size())
    , force_on_material(rigid_bodies.size())
    , forces_on_bodies(rigid_bodies.size())
  {
    unsigned int next = 0;
    for (const auto &body : rigid_bodies)
      if (body.friction != RigidBody<dim>::Friction::frictionless)
        {
          friction_slot_base.push_back(next);
          next += 2 * dim * probes_per_face;
        }
      else
        friction_slot_base.push_back(numbers::invalid_unsigned_int);
  }



  template <int dim>
  bool
  RigidContact<dim>::has_friction(
    const std::vector<RigidBody<dim>> &rigid_bodies)
  {
    for (const auto &body : rigid_bodies)
      if (body.friction != RigidBody<dim>::Friction::frictionless)
        return true;
    return false;
  }



  template <int dim>
  unsigned int
  RigidContact<dim>::max_face_points(
    const std::vector<RigidBody<dim>> &rigid_bodies)
  {
    unsigned int largest = 1;
    for (const auto &body : rigid_bodies)
      {
        unsigned int n = 1;
        for (unsigned int d = 1; d < dim; ++d)
          n *= body.face_points();
        largest = std::max(largest, n);
      }
    return largest;
  }



  template <int dim>
  unsigned int
  RigidContact<dim>::traction_entries(
    const std::vector<RigidBody<dim>> &rigid_bodies)
  {
    // dim per probe of each face, for each body with friction: two bodies
    // may touch the same face.
    const unsigned int n_frictional = std::count_if(
      rigid_bodies.begin(), rigid_bodies.end(), [](const RigidBody<dim> &body) {
        return body.friction != RigidBody<dim>::Friction::frictionless;
      });
    return n_frictional * 2 * dim * max_face_points(rigid_bodies) * dim;
  }



  template <int dim>
  void
  RigidContact<dim>::check_start(
    const MaterialPoints<dim> &material_points) const
  {
    std::string message;
    for (const auto &point : material_points.particles())
      {
        for (const auto &body : rigid_bodies)
          if (body.proximity(point.get_location(), Tensor<1, dim>()).gap < 0.)
            {
              std::ostringstream out;
              out << "Material point " << point.get_id() << " at ("
                  << point.get_location() << ") starts inside " << body.name
                  << ": a rigid body must start outside the bodies (move it "
                     "or its 'Lower corner', 'Center' or 'Vertices').";
              message = out.str();
              break;
            }
        if (!message.empty())
          break;
      }
    throw_if_any_failed(message,
                        grid.get_triangulation().get_communicator(),
                        false);

    // A body pushed by a force must rest on the material: some face of a
    // point's domain on or inside its surface.
    for (unsigned int b = 0; b < rigid_bodies.size(); ++b)
      {
        const RigidBody<dim> &body = rigid_bodies[b];
        if (body.force_components.empty())
          continue;
        bool touches = false;
        for (const auto &point : material_points.particles())
          {
            const PointState<dim> state(point.get_properties());
            const Tensor<1, dim>  half_length = state.domain_half_length();
            for (unsigned int face = 0; face < 2 * dim && !touches; ++face)
              {
                Point<dim> centre = point.get_location();
                centre[face / 2] +=
                  (face % 2 == 1 ? 1. : -1.) * half_length[face / 2];
                touches = body.proximity(centre, Tensor<1, dim>()).gap <= 0.;
              }
            if (touches)
              break;
          }
        if (Utilities::MPI::max(touches ? 1 : 0,
                                grid.get_triangulation().get_communicator()) ==
            0)
          throw_if_any_failed(
            body.name +
              " is pushed by a force ('Force-driven components') but "
              "touches no material at the start: place it on the material "
              "(a face of a point's domain on or inside its surface).",
            grid.get_triangulation().get_communicator(),
            false);
      }
  }



  template <int dim>
  void
  RigidContact<dim>::begin(const MaterialPoints<dim> &material_points,
                           const LoadStepSystem<dim> &system,
                           const double               start,
                           const double               target)
  {
    const auto &cell_size     = grid.cartesian().cell_size;
    double      smallest_cell = cell_size[0], largest_cell = cell_size[0];
    for (unsigned int d = 1; d < dim; ++d)
      {
        smallest_cell = std::min(smallest_cell, cell_size[d]);
        largest_cell  = std::max(largest_cell, cell_size[d]);
      }
    const auto reach = move_bodies(start, target, largest_cell);

    const unsigned int traction_index =
      material_points.layout().coupling_field(traction_field);
    probes.clear();
    for (const auto &point : material_points.particles())
      {
        const unsigned int    p          = system.point_steps.index_of(point);
        const auto            properties = point.get_properties();
        const PointState<dim> state(properties);
        const Point<dim>      position    = point.get_location();
        const Tensor<1, dim>  half_length = state.domain_half_length();
        // With explicit steps a side also pushes a face that started over
        // it up to half the domain's shortest half-length behind it
        // (use_explicit_steps()).
        double impact_depth = 0.;
        if (explicit_steps)
          {
            impact_depth = 0.5 * half_length[0];
            for (unsigned int d = 1; d < dim; ++d)
              impact_depth = std::min(impact_depth, 0.5 * half_length[d]);
          }
        for (unsigned int face = 0; face < 2 * dim; ++face)
          {
            const unsigned int axis   = face / 2;
            const double       sign   = face % 2 == 1 ? 1. : -1.;
            Point<dim>         centre = position;
            centre[axis] += sign * half_length[axis];
            for (unsigned int b = 0; b < rigid_bodies.size(); ++b)
              {
                bool near = true;
                for (unsigned int d = 0; d < dim; ++d)
                  near = near && centre[d] >= reach[b].first[d] &&
                         centre[d] <= reach[b].second[d];
                if (!near)
                  continue;
                const RigidBody<dim> &body = rigid_bodies[b];
                Probe                 probe;
                probe.point             = p;
                probe.body              = b;
                probe.face_normal       = Tensor<1, dim>();
                probe.face_normal[axis] = sign;
                probe.facing.normal =
                  body.rotates() ? transpose(rotation[b]) * probe.face_normal :
                                   probe.face_normal;
                // The penalty lets a face in by p h / (alpha E), less than
                // h / alpha for any pressure below E; an explicit step's
                // impact may press it deeper.
                probe.facing.tolerance = smallest_cell / body.penalty_factor;
                probe.facing.deep_tolerance =
                  std::max(probe.facing.tolerance, impact_depth);
                probe.facing.half_length = half_length;
                double face_area         = 1.;
                for (unsigned int d = 0; d < dim; ++d)
                  if (d != axis)
                    face_area *= 2. * half_length[d];
                const double modulus =
                  system.point_steps[p].material->elastic_modulus();
                probe.stiffness = body.penalty_factor * modulus / smallest_cell;
                probe.tangential_stiffness =
                  body.tangential_penalty_factor * modulus / smallest_cell;
                system.face_weights(
                  p, position, half_length, axis, sign, probe.weights);
                // The face's Gauss points (a box: its centre, with the
                // face's overlap), each moving with the face's mean
                // displacement.
                const unsigned int per_direction = body.face_points();
                const QGauss<1>    gauss(per_direction);
                unsigned int       n_points = 1;
                for (unsigned int d = 1; d < dim; ++d)
                  n_points *= per_direction;
                for (unsigned int k = 0; k < n_points; ++k)
                  {
                    Point<dim>   at     = centre;
                    double       weight = 1.;
                    unsigned int rest   = k;
                    for (unsigned int d = 0; d < dim; ++d)
                      if (d != axis)
                        {
                          const unsigned int i = rest % per_direction;
                          rest /= per_direction;
                          at[d] +=
                            (2. * gauss.point(i)[0] - 1.) * half_length[d];
                          weight *= gauss.weight(i);
                        }
                    probe.slot =
                      friction_slot_base[b] == numbers::invalid_unsigned_int ?
                        numbers::invalid_unsigned_int :
                        friction_slot_base[b] + face * probes_per_face + k;
                    probe.start_position = at;
                    probe.facing.start =
                      body.rotates() ? body.to_body_frame(at,
                                                          start_displacement[b],
                                                          start_rotation[b]) :
                                       at - start_displacement[b];
                    // In axisymmetry the ring the Gauss point sweeps.
                    probe.area =
                      weight * face_area * grid.cartesian().ring_length(at);
                    // In axisymmetry a Gauss point on the axis sweeps no
                    // ring: no force, and a contact state of round-off.
                    if (probe.area == 0.)
                      continue;
                    if (probe.slot != numbers::invalid_unsigned_int)
                      for (unsigned int d = 0; d < dim; ++d)
                        probe.previous_traction[d] =
                          properties[traction_index + probe.slot * dim + d];
                    probes.push_back(probe);
                  }
              }
          }
      }
  }



  template <int dim>
  void
  RigidContact<dim>::evaluate(Probe &probe, const Point<dim> &position) const
  {
    const RigidBody<dim> &body      = rigid_bodies[probe.body];
    const auto            proximity = body.proximity(position,
                                          displacement[probe.body],
                                          rotation[probe.body],
                                          &probe.facing);
    const Tensor<1, dim> &n         = proximity.normal;
    const Tensor<2, dim> &H         = proximity.normal_derivative;
    // The face's share of the body's surface: its area projected on the
    // tangent plane. A face at right angles to the surface has none; its
    // cosine, exactly zero for an unturned body (a quarter model's faces on
    // a symmetry plane), is of the order of round-off (1e-17) for a turned
    // one and must not decide whether the face is in contact.
    const double c = -(probe.face_normal * n);
    probe.active   = proximity.gap <= 0. && c > perpendicular_cosine;
    probe.slipping = false;
    probe.piece    = probe.active ? proximity.piece : 0;
    if (!probe.active)
      {
        probe.normal_force     = Tensor<1, dim>();
        probe.friction_force   = Tensor<1, dim>();
        probe.traction         = Tensor<1, dim>();
        probe.force_derivative = Tensor<2, dim>();
        return;
      }
    const double          k        = probe.stiffness;
    const double          A        = probe.area;
    const double          pressure = -k * proximity.gap;
    const double          w        = proximity.overlap;
    const Tensor<1, dim> &dw       = proximity.overlap_gradient;
    const Tensor<1, dim>  dc       = -(H * probe.face_normal);
    const Tensor<2, dim>  identity = unit_symmetric_tensor<dim>();
    // The pressure on the part w of the face's area projected on the
    // tangent plane, A c w.
    probe.normal_force = A * c * w * pressure * n;
    // d(A c w p n)/dx, with dp/dx = -k n and dn/dx = H.
    probe.force_derivative =
      A *
      (outer_product(n, w * (-k * c * n + pressure * dc) + c * pressure * dw) +
       c * w * pressure * H);

    probe.traction       = Tensor<1, dim>();
    probe.friction_force = Tensor<1, dim>();
    if (body.friction == RigidBody<dim>::Friction::frictionless)
      return;
    // Trial traction: the traction of the step before and the slip of the
    // face against the body in this step, on the tangent plane.
    // A turning body carries the traction of the step before along, and
    // the slip is the face's motion relative to the body's material:
    // (x - c - d) - dR (x^n - c - d^n), dR the rotation over the step
    // (derivative I).
    Tensor<1, dim> slip, previous_traction = probe.previous_traction;
    if (body.rotates())
      {
        const Tensor<2, dim> &turn = rotation_increment[probe.body];
        slip = (position - body.rotation_centre - displacement[probe.body]) -
               turn * (probe.start_position - body.rotation_centre -
                       start_displacement[probe.body]);
        previous_traction = turn * previous_traction;
      }
    else
      slip =
        (position - probe.start_position) - displacement_increment[probe.body];
    const double         kt         = probe.tangential_stiffness;
    const Tensor<1, dim> v          = previous_traction + kt * slip;
    const Tensor<2, dim> projection = identity - outer_product(n, n);
    const Tensor<1, dim> trial      = projection * v;
    const Tensor<2, dim> d_trial =
      kt * projection - (n * v) * H - outer_product(n, H * v);
    const double   trial_norm = trial.norm();
    const double   limit      = body.friction_coefficient * pressure;
    Tensor<2, dim> d_traction;
    if (body.friction == RigidBody<dim>::Friction::rough || trial_norm <= limit)
      {
        probe.traction = trial;
        d_traction     = d_trial;
      }
    else
      {
        probe.slipping         = true;
        const Tensor<1, dim> m = trial / trial_norm;
        probe.traction         = limit * m;
        d_traction =
          outer_product(m, -body.friction_coefficient * k * n) +
          (limit / trial_norm) * ((identity - outer_product(m, m)) * d_trial);
      }
    probe.friction_force = -A * c * w * probe.traction;
    probe.force_derivative -=
      A * (outer_product(probe.traction, w * dc + c * dw) + c * w * d_traction);
  }



  template <int dim>
  void
  RigidContact<dim>::add_forces(const LoadStepSystem<dim> &system,
                                const NodalVector         &increment,
                                NodalVector               &internal_force)
  {
    for (auto &force : force_on_material)
      force = Tensor<1, dim>();
    round_off_squared = 0.;
    for (Probe &probe : probes)
      {
        const PointStep<dim> &step     = system.point_steps[probe.point];
        Point<dim>            position = probe.start_position;
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            position[i] += probe.weights[v] *
                           increment.local_element(step.dofs[v * dim + i]);
        const bool was_active = probe.active, was_slipping = probe.slipping;
        const unsigned int was_piece = probe.piece;
        evaluate(probe, position);
        probe.changed = probe.active != was_active ||
                        probe.slipping != was_slipping ||
                        probe.piece != was_piece;
        if (!probe.active)
          continue;
        double size = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          size = std::max({size,
                           std::abs(position[d]),
                           std::abs(displacement[probe.body][d])});
        round_off_squared +=
          std::pow(std::numeric_limits<double>::epsilon() *
                     (probe.stiffness + probe.tangential_stiffness) *
                     probe.area * size,
                   2);
        force_on_material[probe.body] +=
          probe.normal_force + probe.friction_force;
        subtract_probe_force(probe, system, internal_force);
      }
  }



  template <int dim>
  void
  RigidContact<dim>::subtract_probe_force(const Probe               &probe,
                                          const LoadStepSystem<dim> &system,
                                          NodalVector &internal_force) const
  {
    const PointStep<dim> &step  = system.point_steps[probe.point];
    const Tensor<1, dim>  force = probe.normal_force + probe.friction_force;
    for (unsigned int v = 0; v < step.support.n_nodes; ++v)
      for (unsigned int i = 0; i < dim; ++i)
        internal_force.local_element(step.dofs[v * dim + i]) -=
          probe.weights[v] * force[i];
  }



  template <int dim>
  bool
  RigidContact<dim>::state_changed() const
  {
    bool changed = false;
    for (const Probe &probe : probes)
      changed = changed || probe.changed;
    return Utilities::MPI::max(changed ? 1 : 0,
                               grid.get_triangulation().get_communicator()) ==
           1;
  }



  template <int dim>
  void
  RigidContact<dim>::add_contact_matrix(
    const LoadStepSystem<dim>      &system,
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    for (const Probe &probe : probes)
      {
        if (!probe.active)
          continue;
        const PointStep<dim> &step = system.point_steps[probe.point];
        const unsigned int    n    = step.support.n_nodes * dim;
        for (unsigned int r = 0; r < n; ++r)
          {
            const auto row = system.system_index(step.dofs[r]);
            if (row == numbers::invalid_dof_index ||
                probe.weights[r / dim] == 0.)
              continue;
            for (unsigned int s = 0; s < n; ++s)
              {
                const auto   column = system.system_index(step.dofs[s]);
                const double value  = -probe.weights[r / dim] *
                                     probe.weights[s / dim] *
                                     probe.force_derivative[r % dim][s % dim];
                if (column != numbers::invalid_dof_index && value != 0.)
                  matrix.add(row, column, value);
              }
          }
      }
  }



  template <int dim>
  void
  RigidContact<dim>::accept(MaterialPoints<dim>       &material_points,
                            const LoadStepSystem<dim> &system,
                            const NodalVector &)
  {
    for (const auto &[body, component] : body_unknowns)
      accepted_unknowns[body][component] = displacement[body][component];
    for (auto &force : forces_on_bodies)
      force = BodyForce();
    std::vector<double> tractions;
    if (friction)
      tractions.assign(material_points.n_local_points() * n_traction_entries,
                       0.);
    for (const Probe &probe : probes)
      {
        if (!probe.active)
          continue;
        BodyForce &force = forces_on_bodies[probe.body];
        force.normal -= probe.normal_force;
        force.tangential -= probe.friction_force;
        ++force.n_contacts;
        force.n_slipping += probe.slipping ? 1 : 0;
        if (probe.slot != numbers::invalid_unsigned_int)
          for (unsigned int d = 0; d < dim; ++d)
            tractions[probe.point * n_traction_entries + probe.slot * dim + d] =
              probe.traction[d];
      }
    const MPI_Comm communicator = grid.get_triangulation().get_communicator();
    for (BodyForce &force : forces_on_bodies)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            force.normal[d] =
              Utilities::MPI::sum(force.normal[d], communicator);
            force.tangential[d] =
              Utilities::MPI::sum(force.tangential[d], communicator);
          }
        force.n_contacts = Utilities::MPI::sum(force.n_contacts, communicator);
        force.n_slipping = Utilities::MPI::sum(force.n_slipping, communicator);
        force.total      = force.normal + force.tangential;
      }
    if (friction)
      material_points.set_coupling_field(traction_field,
                                         system.point_steps,
                                         tractions);
  }



  template <int dim>
  std::vector<std::string>
  RigidContact<dim>::descriptions() const
  {
    std::vector<std::string> lines;
    for (const auto &body : rigid_bodies)
      lines.push_back(body.description());
    return lines;
  }



  template class RigidContact<2>;
  template class RigidContact<3>;

} // namespace impm
