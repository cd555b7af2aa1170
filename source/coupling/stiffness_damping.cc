// The stiffness-proportional part of Rayleigh damping: a viscous stress
// of the elastic moduli and the nodal velocity's rate of strain.
#include <impm/core/point_properties.h>
#include <impm/coupling/stiffness_damping.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace impm
{
  template <int dim>
  StiffnessDamping<dim>::StiffnessDamping(const TimeIntegrator &integrator)
    : coefficient(integrator.stiffness_damping)
    , gamma_over_beta(
        integrator.is_explicit() ? 0. : integrator.gamma / integrator.beta)
    , k_r(integrator.alpha_f / (1. - integrator.alpha_f))
  {}



  template <int dim>
  void
  StiffnessDamping<dim>::begin_step(const MaterialPoints<dim> &material_points,
                                    const PointSteps<dim>     &steps)
  {
    if (!active())
      return;
    scaled_moduli.resize(steps.size());
    for (const auto &point : material_points.particles())
      {
        const Material &material = *steps.of(point).material;
        const double    scale =
          coefficient * PointState<dim>(point.get_properties()).volume();
        const double mu                      = material.shear_modulus();
        scaled_moduli[steps.index_of(point)] = {
          scale * (material.p_wave_modulus() - 2. * mu), scale * mu};
      }
  }



  template <int dim>
  double
  StiffnessDamping<dim>::critical_time_step(const double undamped_step) const
  {
    const double zeta = coefficient / undamped_step;
    return undamped_step * (std::sqrt(1. + zeta * zeta) - zeta);
  }



  template <int dim>
  double
  StiffnessDamping<dim>::add_force(const LoadStepSystem<dim> &system,
                                   const std::vector<double> &nodal_velocity,
                                   NodalVector               &force) const
  {
    const bool axisymmetric = system.axisymmetric();
    double     squares      = 0.;
    for (unsigned int p = 0; p < system.point_steps.size(); ++p)
      {
        const PointStep<dim> &step = system.point_steps[p];
        const auto           &s    = step.support;
        Tensor<2, dim>        rate; // the velocity's gradient
        double                hoop_rate = 0.;
        for (unsigned int v = 0; v < s.n_nodes; ++v)
          {
            for (unsigned int i = 0; i < dim; ++i)
              rate[i] +=
                nodal_velocity[step.dofs[v * dim + i]] * s.gradients[v];
            if (axisymmetric)
              hoop_rate +=
                s.hoop_weights[v] * nodal_velocity[step.dofs[v * dim]];
          }
        // V sigma_d = beta_R V (lambda tr I + 2 mu sym(L))
        const auto [lambda, mu]    = scaled_moduli[p];
        const double   volume_rate = trace(rate) + hoop_rate;
        Tensor<2, dim> stress      = mu * (rate + transpose(rate));
        for (unsigned int i = 0; i < dim; ++i)
          stress[i][i] += lambda * volume_rate;
        const double hoop_stress = lambda * volume_rate + 2. * mu * hoop_rate;
        for (unsigned int v = 0; v < s.n_nodes; ++v)
          {
            const Tensor<1, dim> f = stress * s.gradients[v];
            for (unsigned int i = 0; i < dim; ++i)
              force.local_element(step.dofs[v * dim + i]) += f[i];
            squares += f.norm_square();
            if (axisymmetric)
              {
                const double hoop_force = hoop_stress * s.hoop_weights[v];
                force.local_element(step.dofs[v * dim]) += hoop_force;
                squares += hoop_force * (hoop_force + 2. * f[0]);
              }
          }
      }
    return squares;
  }



  template <int dim>
  double
  StiffnessDamping<dim>::add_implicit_forces(const NodalMomentum<dim>  &nodes,
                                             const LoadStepSystem<dim> &system,
                                             const NodalVector &increment,
                                             const double       time_step,
                                             NodalVector       &internal_force)
  {
    velocity.resize(nodes.n_local());
    for (unsigned int i = 0; i < nodes.n_local(); ++i)
      {
        const double du = increment.local_element(i);
        const double m  = nodes.mass(i);
        if (!nodes.in_system(i) || !(m > 0.))
          {
            velocity[i] = (1. + k_r) * du / time_step;
            continue;
          }
        // With a^{n+1} from the Newmark relation, v^{n+1} = v + dt ((1 -
        // gamma) a + gamma a^{n+1}) = (gamma/beta) du/dt + (1 -
        // gamma/beta) v + dt (1 - gamma/(2 beta)) a.
        const double v = nodes.momentum(i) / m;
        const double a = nodes.mass_acceleration(i) / m;
        velocity[i]    = gamma_over_beta * du / time_step +
                      (1. - gamma_over_beta) * v +
                      time_step * (1. - 0.5 * gamma_over_beta) * a + k_r * v;
      }
    return add_force(system, velocity, internal_force);
  }



  template <int dim>
  void
  StiffnessDamping<dim>::add_implicit_matrix(
    const LoadStepSystem<dim>      &system,
    const double                    time_step,
    TrilinosWrappers::SparseMatrix &matrix)
  {
    const bool   axisymmetric = system.axisymmetric();
    const double factor       = gamma_over_beta / time_step;
    const auto  &steps        = system.point_steps;
    // One dense block per assembly group (the points that share a support,
    // LoadStepSystem::assembly_groups): K_(vi)(wk) = V (lambda b_vi b_wk +
    // mu (delta_ik g_v.g_w + g_vk g_wi) + 2 mu delta_i0 delta_k0 h_v h_w),
    // b_vi = g_vi + delta_i0 h_v (h the hoop weights, axisymmetry only).
    std::array<unsigned int, PointSupport<dim>::max_nodes> position;
    for (const AssemblyGroup &group : system.assembly_groups)
      {
        const unsigned int n = group.n_nodes * dim;
        block.assign(n * n, 0.);
        const unsigned char *node_positions = group.node_positions.data();
        for (const unsigned int p : group.points)
          {
            const PointStep<dim> &step = steps[p];
            const auto           &s    = step.support;
            for (unsigned int v = 0; v < s.n_nodes; ++v)
              position[v] =
                group.node_positions.empty() ? v : *node_positions++;
            const double lambda = factor * scaled_moduli[p].first;
            const double mu     = factor * scaled_moduli[p].second;
            for (unsigned int v = 0; v < s.n_nodes; ++v)
              for (unsigned int w = 0; w < s.n_nodes; ++w)
                {
                  const Tensor<1, dim> &g_v = s.gradients[v],
                                       &g_w = s.gradients[w];
                  const double h_v = axisymmetric ? s.hoop_weights[v] : 0.;
                  const double h_w = axisymmetric ? s.hoop_weights[w] : 0.;
                  const double gg  = mu * (g_v * g_w);
                  for (unsigned int i = 0; i < dim; ++i)
                    {
                      double *row =
                        &block[(position[v] * dim + i) * n + position[w] * dim];
                      const double b_vi = g_v[i] + (i == 0 ? h_v : 0.);
                      for (unsigned int k = 0; k < dim; ++k)
                        row[k] +=
                          lambda * b_vi * (g_w[k] + (k == 0 ? h_w : 0.)) +
                          mu * g_v[k] * g_w[i] + (i == k ? gg : 0.);
                      if (i == 0)
                        row[0] += 2. * mu * h_v * h_w;
                    }
                }
          }
        const unsigned int n_rows = group.rows.size();
        row_offsets.resize(n_rows);
        column_offsets.resize(n_rows);
        for (unsigned int a = 0; a < n_rows; ++a)
          {
            row_offsets[a]    = group.local[a] * n;
            column_offsets[a] = group.local[a];
          }
        block_adder.add(group.rows.data(),
                        n_rows,
                        StoredBlock{block.data(),
                                    row_offsets.data(),
                                    column_offsets.data()},
                        matrix,
                        system.off_process_rows);
      }
  }



  template <int dim>
  const NodalVector &
  StiffnessDamping<dim>::damped_residual(const NodalMomentum<dim>  &nodes,
                                         const LoadStepSystem<dim> &system,
                                         const NodalVector         &residual)
  {
    velocity.resize(nodes.n_local());
    for (unsigned int i = 0; i < nodes.n_local(); ++i)
      velocity[i] = nodes.in_system(i) && nodes.mass(i) > 0. ?
                      nodes.momentum(i) / nodes.mass(i) :
                      0.;
    damping_force.reinit(residual);
    add_force(system, velocity, damping_force);
    damping_force.compress(VectorOperation::add);
    residual_with_damping = damping_force;
    residual_with_damping.add(1., residual);
    residual_with_damping.update_ghost_values();
    return residual_with_damping;
  }



  template <int dim>
  double
  StiffnessDamping<dim>::implicit_dissipation(const NodalMomentum<dim>  &nodes,
                                              const LoadStepSystem<dim> &system,
                                              const NodalVector &increment,
                                              const double       time_step)
  {
    if (!active())
      return 0.;
    NodalVector force;
    force.reinit(increment);
    add_implicit_forces(nodes, system, increment, time_step, force);
    force.compress(VectorOperation::add);
    // The force is that of the weighted velocity v^{n+1} + k_r v^n, the
    // balance at t_{n+1-alpha_f} divided by 1 - alpha_f = 1 / (1 + k_r):
    // the viscous stress's work over the step is the weighted one's.
    double dissipation = 0.;
    for (unsigned int i = 0; i < force.locally_owned_size(); ++i)
      dissipation += force.local_element(i) * increment.local_element(i);
    return dissipation / (1. + k_r);
  }



  template <int dim>
  double
  StiffnessDamping<dim>::explicit_dissipation(
    const std::vector<double> &increment,
    const unsigned int         n_owned) const
  {
    double dissipation = 0.;
    for (unsigned int i = 0; i < n_owned; ++i)
      dissipation += damping_force.local_element(i) * increment[i];
    return dissipation;
  }



  template class StiffnessDamping<2>;
  template class StiffnessDamping<3>;
} // namespace impm
