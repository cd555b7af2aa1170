#ifndef impm_coupling_couplings_h
#define impm_coupling_couplings_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/vector.h>

#include <impm/coupling/coupling.h>
#include <impm/coupling/step_energy.h>
#include <impm/points/material_points.h>
#include <impm/system/load_step_system.h>

#include <memory>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The scene's couplings, in the order of their names, and the loops
   * over them that the load-step code calls.
   */
  template <int dim>
  class Couplings
  {
  public:
    /** @brief Declare the subsections of the registered couplings that
     *  declare parameters. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** @brief Create the couplings the scene asks for. */
    explicit Couplings(const CouplingInputs<dim> &inputs);

    /** @brief The couplings. */
    const std::vector<std::unique_ptr<Coupling<dim>>> &
    list() const
    {
      return couplings;
    }

    /** @brief The coupling of type @p Type, or nullptr. */
    template <typename Type>
    const Type *
    find() const
    {
      for (const auto &coupling : couplings)
        if (const auto *found = dynamic_cast<const Type *>(coupling.get()))
          return found;
      return nullptr;
    }

    /** @brief The coupling that sets the points' volumes, or nullptr. */
    Coupling<dim> *
    volume_coupling() const
    {
      return sets_volumes;
    }

    /** @brief The fields all couplings store per point. */
    PointFields
    point_fields() const;

    /** @brief Whether any coupling needs a direct linear solver. */
    bool
    need_direct_solver() const;

    /** @brief The total number of unknowns shared by all processes. */
    unsigned int
    n_global_unknowns() const
    {
      return n_global;
    }

    /**
     * @brief The setup of a load step's system (LoadStepSystem::number(),
     * the couplings' prepare() and setup(), LoadStepSystem::make_pattern()).
     * Returns whether the matrix of the step before was kept. Collective.
     */
    bool
    set_up_system(const MaterialPoints<dim> &material_points,
                  LoadStepSystem<dim>       &system);

    /** @brief The coupling that finds each step's increment itself
     *  (Coupling::solves_step(): explicit time integration), or null. */
    Coupling<dim> *
    step_solver() const;

    /** @brief Sum of every coupling's force_from_material(). */
    Tensor<1, dim>
    force_from_material() const;

    /** @brief Whether a coupling keeps the scene's energy balance. */
    bool
    keep_energy_balance() const;

    /** @brief The first coupling's Coupling::run_failure() (empty if
     *  none has one). */
    std::string
    run_failure() const;

    /** @brief Tell the keepers of the energy balance what the converged
     *  step with displacement increment @p increment moved: @p
     *  work_of_loads (the loads' and the faces' work on the material,
     *  summed over the processes) and every coupling's
     *  Coupling::add_step_energy(). Before the couplings' accept().
     *  Collective. */
    void
    account_step_energy(const LoadStepSystem<dim> &system,
                        const NodalVector         &increment,
                        const double               work_of_loads) const;

    /** @brief Whether any coupling's state changed. Collective. */
    bool
    state_changed() const;

    /** @brief The global unknowns' residuals, coupling after coupling.
     *  Collective. */
    Vector<double>
    global_residuals() const;

    /** @brief Add @p correction to the global unknowns, coupling after
     *  coupling. */
    void
    add_to_global_unknowns(const Vector<double> &correction) const;

    /** @brief Why global unknown @p j cannot be solved for. */
    std::string
    unbalanced_unknown(const unsigned int j) const;

  private:
    std::vector<std::unique_ptr<Coupling<dim>>> couplings;
    Coupling<dim>                              *sets_volumes = nullptr;
    unsigned int                                n_global     = 0;
  };
} // namespace impm

#endif
