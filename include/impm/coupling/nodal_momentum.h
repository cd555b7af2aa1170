#ifndef impm_coupling_nodal_momentum_h
#define impm_coupling_nodal_momentum_h

#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/points/point_step.h>
#include <impm/system/dense_block_adder.h>
#include <impm/system/load_step_system.h>

#include <array>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The transfer of mass and momentum between the material points
   * and the nodes of a step's grid, for the time integrators (Inertia).
   *
   * map_points() sums the points' mass, momentum and mass times
   * acceleration at the nodes with the step's weights @f$N_{Ip}@f$ (a
   * lumped mass: @f$M_I = \sum_p N_{Ip} m_p@f$, @f$p_I = \sum_p N_{Ip} m_p
   * v_p@f$, @f$q_I = \sum_p N_{Ip} m_p a_p@f$), with the momentum and
   * acceleration zero on the DoFs outside the system (constrained: their
   * motion is prescribed). update_points() takes the nodes' new state
   * back to the points, remapped_velocity() maps the points' updated
   * momentum to the nodes again (the modified update, MUSL).
   *
   * With the affine transfer (APIC) each point also carries the gradient
   * @f$C_p@f$ of the nodes' velocity (the declared point field
   * `velocity_gradient`, row-major) and gives the nodes the momentum of
   * the affine field about the centre of its weights, @f$\bar x_p =
   * \sum_I N_{Ip} x_I / \sum_I N_{Ip}@f$: @f$p_I = \sum_p N_{Ip} m_p (v_p +
   * C_p (x_I - \bar x_p))@f$. The affine part adds no momentum in total
   * (@f$\sum_I N_{Ip}(x_I - \bar x_p) = 0@f$), and a velocity field linear
   * in space (a rigid rotation) reaches the nodes exactly, however few
   * points share them.
   *
   * The points' velocity and acceleration are the declared point fields
   * `velocity` and `acceleration` of the couplings (PointLayout).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class NodalMomentum
  {
  public:
    /** @brief Transfers on @p grid; with @p affine those of APIC. */
    NodalMomentum(const BackgroundGrid<dim> &grid, const bool affine);

    /** @brief Map the points' mass, momentum and mass times acceleration
     *  to the nodes of this step (owned and ghost DoFs). Collective. */
    void
    map_points(const MaterialPoints<dim> &material_points,
               const LoadStepSystem<dim> &system);

    /** @brief Number of local DoFs (owned, then ghosts). */
    unsigned int
    n_local() const
    {
      return in_system_dof.size();
    }

    /** @brief The lumped mass of local DoF @p i. */
    double
    mass(const unsigned int i) const
    {
      return nodal_mass.local_element(i);
    }

    /** @brief The momentum of local DoF @p i (zero outside the system). */
    double
    momentum(const unsigned int i) const
    {
      return nodal_momentum.local_element(i);
    }

    /** @brief The norm of the nodal momentum over all processes
     *  (collective). */
    double
    momentum_norm() const
    {
      return nodal_momentum.l2_norm();
    }

    /** @brief The mass times acceleration of local DoF @p i. */
    double
    mass_acceleration(const unsigned int i) const
    {
      return nodal_mass_acceleration.local_element(i);
    }

    /** @brief Set the mass times acceleration of local DoF @p i. */
    void
    set_mass_acceleration(const unsigned int i, const double value)
    {
      nodal_mass_acceleration.local_element(i) = value;
    }

    /** @brief Whether local DoF @p i is an unknown of the system. */
    bool
    in_system(const unsigned int i) const
    {
      return in_system_dof[i];
    }

    /**
     * @brief The points' new velocity and acceleration from the nodes'
     * (local DoFs): @f$v_p = \phi\,(v_p + \sum_I N_{Ip}\,\Delta v_I) + (1 -
     * \phi) \sum_I N_{Ip}\, v_I^{n+1}@f$ (FLIP fraction @f$\phi@f$),
     * @f$a_p = \sum_I N_{Ip}\, a_I@f$; with the affine transfer @f$v_p =
     * \sum_I N_{Ip}\, v_I^{n+1}@f$ (velocity_gradients() gives its
     * gradient).
     * @param material_points The points (their velocity at the start).
     * @param steps The points' data of the step (their weights).
     * @param flip_fraction The FLIP fraction @f$\phi@f$.
     * @param velocity_change, new_velocity, new_acceleration The nodes'
     *   @f$\Delta v_I@f$, @f$v_I^{n+1}@f$ and @f$a_I@f$ on the local DoFs.
     * @param[out] velocities, accelerations By step index and axis.
     */
    void
    update_points(const MaterialPoints<dim> &material_points,
                  const PointSteps<dim>     &steps,
                  const double               flip_fraction,
                  const std::vector<double> &velocity_change,
                  const std::vector<double> &new_velocity,
                  const std::vector<double> &new_acceleration,
                  std::vector<double>       &velocities,
                  std::vector<double>       &accelerations) const;

    /**
     * @brief The gradient at each point of the nodal velocity @p velocity
     * (local DoFs), @f$C_p = \sum_I v_I \otimes \nabla N_{Ip}@f$, by step
     * index and its dim x dim entries (row-major): the affine transfer's
     * `velocity_gradient`.
     */
    std::vector<double>
    velocity_gradients(const MaterialPoints<dim> &material_points,
                       const PointSteps<dim>     &steps,
                       const std::vector<double> &velocity) const;

    /**
     * @brief The nodes' velocity of the points' momentum with the
     * velocities @p velocities (by step index and axis; with the affine
     * transfer, and their gradients @p velocity_gradients, by step index
     * and dim x dim), over the mass of map_points(), on the local DoFs of
     * the system (zero elsewhere). Collective.
     */
    std::vector<double>
    remapped_velocity(const MaterialPoints<dim> &material_points,
                      const PointSteps<dim>     &steps,
                      const std::vector<double> &velocities,
                      const std::vector<double> &velocity_gradients) const;

    /**
     * @brief The consistent mass matrix times @p x (ghosted local DoFs):
     * @f$(M x)_I = \sum_p N_{Ip}\, m_p \sum_J N_{Jp} x_J@f$ on the local
     * DoFs, owned and ghost, summed over the processes. Collective.
     */
    std::vector<double>
    consistent_mass_times(const MaterialPoints<dim> &material_points,
                          const PointSteps<dim>     &steps,
                          const NodalVector         &x) const;

    /**
     * @brief The value at each point of the nodal field @p x (ghosted
     * local DoFs): @f$x_p = \sum_I N_{Ip} x_I@f$, by step index and axis.
     */
    std::vector<double>
    at_points(const MaterialPoints<dim> &material_points,
              const PointSteps<dim>     &steps,
              const NodalVector         &x) const;

    /**
     * @brief The nodes' velocity and acceleration of the consistent mass:
     * @f$M v = p@f$ and @f$M a = q@f$ with @f$M = M_c + \epsilon M_L@f$
     * (the consistent matrix, plus @p regularisation times the lumped
     * one, which keeps M definite where few points share a node), on the
     * system's DoFs (zero elsewhere), by conjugate gradients
     * preconditioned with the lumped mass, to 1e-12 of the right-hand
     * side. A solve that does not converge is an error. Collective.
     * @param material_points The points.
     * @param steps The points' data of the step (their weights).
     * @param regularisation The factor @f$\epsilon@f$ of the lumped mass.
     * @param[out] velocity, acceleration On the local DoFs (owned and
     *   ghosts).
     */
    void
    consistent_velocity_and_acceleration(
      const MaterialPoints<dim> &material_points,
      const PointSteps<dim>     &steps,
      const double               regularisation,
      std::vector<double>       &velocity,
      std::vector<double>       &acceleration) const;

    /**
     * @brief The nodes' velocity and acceleration of the step's start:
     * the momentum and mass times acceleration over the lumped mass (zero
     * where it is zero), or with @p consistent those of
     * consistent_velocity_and_acceleration(). Collective if @p consistent.
     * @param material_points The points.
     * @param steps The points' data of the step (their weights).
     * @param consistent Whether the mass is consistent.
     * @param regularisation With the consistent mass, the factor of the
     *   lumped mass added to it.
     * @param[out] velocity, acceleration On the local DoFs (owned and
     *   ghosts).
     */
    void
    start_velocity_and_acceleration(const MaterialPoints<dim> &material_points,
                                    const PointSteps<dim>     &steps,
                                    const bool                 consistent,
                                    const double               regularisation,
                                    std::vector<double>       &velocity,
                                    std::vector<double> &acceleration) const;

    /**
     * @brief Add @p c times the consistent mass matrix, @f$c \sum_p m_p
     * N_{Ip} N_{Jp}@f$ per axis, to @p matrix: one dense block per point
     * on its nodes' rows of the system (those of other processes through
     * the system's off-process rows).
     */
    void
    add_consistent_mass(const double                    c,
                        const MaterialPoints<dim>      &material_points,
                        const LoadStepSystem<dim>      &system,
                        TrilinosWrappers::SparseMatrix &matrix);

  private:
    /**
     * @brief @f$\sum_p N_{Ip}\, m_p\, x_p@f$ of the point values @p values
     * (by step index and axis) at the nodes, summed over the processes and
     * ghosted; with @p gradients (by step index, dim x dim), @f$\sum_p
     * N_{Ip}\, m_p (x_p + G_p (x_I - \bar x_p))@f$. Collective.
     */
    NodalVector
    mass_weighted_sum(const MaterialPoints<dim> &material_points,
                      const PointSteps<dim>     &steps,
                      const std::vector<double> &values,
                      const double              *gradients) const;

    /**
     * @brief The affine field's value at each node of a point's support
     * less its value at the centre of the weights: @f$G (x_v - \bar
     * x_p)@f$, by node and axis, for the gradient @p gradient (dim x dim,
     * row-major).
     */
    std::array<double, PointSupport<dim>::max_nodes * dim>
    affine_parts(const PointStep<dim> &step, const double *gradient) const;

    /** @brief Solve @f$(M_c + \epsilon M_L) x = b@f$ (see
     *  consistent_velocity_and_acceleration()). */
    std::vector<double>
    solve_consistent_mass(const MaterialPoints<dim> &material_points,
                          const PointSteps<dim>     &steps,
                          const double               regularisation,
                          const NodalVector         &right_hand_side) const;

    const BackgroundGrid<dim> &grid;
    /** Whether the transfer is APIC's. */
    const bool affine;
    /** The scratch of the consistent mass matrix's point blocks. */
    DenseBlockAdder   block_adder;
    NodalVector       nodal_mass, nodal_momentum, nodal_mass_acceleration;
    std::vector<bool> in_system_dof;
  };
} // namespace impm

#endif
