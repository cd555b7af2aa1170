#ifndef impm_coupling_fixed_nodal_load_h
#define impm_coupling_fixed_nodal_load_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <impm/grid/background_grid.h>
#include <impm/system/load_step_system.h>

#include <cmath>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief A nodal load that a coupling makes at the start of a load
   * step's attempt and that does not depend on the step's increment (no
   * matrix): applied at the DoFs of the system (the held ones keep their
   * reactions), with its size for the residual's reference and its sum
   * for the balance of the reactions. The load of a shaken base and the
   * released initial stress are two.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class FixedNodalLoad
  {
  public:
    /** @brief The load, zero on every local DoF: add to it (ghosts
     *  included), then call finish(). */
    NodalVector &
    reset(const BackgroundGrid<dim> &grid)
    {
      grid.reinit_vector(load);
      return load;
    }

    /** @brief Sum the ghosts' shares into their owners, mark the owned
     *  DoFs of the system and take the load's norm and sum over them.
     *  Collective. */
    void
    finish(const LoadStepSystem<dim> &system, const BackgroundGrid<dim> &grid)
    {
      load.compress(VectorOperation::add);
      in_system.resize(load.locally_owned_size());
      Tensor<1, dim> local_total;
      double         norm_squared = 0.;
      for (unsigned int i = 0; i < load.locally_owned_size(); ++i)
        {
          in_system[i] = system.system_index(i) != numbers::invalid_dof_index;
          if (in_system[i])
            {
              local_total[grid.component(i)] += load.local_element(i);
              norm_squared += load.local_element(i) * load.local_element(i);
            }
        }
      const MPI_Comm communicator = grid.get_triangulation().get_communicator();
      for (unsigned int d = 0; d < dim; ++d)
        total[d] = Utilities::MPI::sum(local_total[d], communicator);
      load_norm = std::sqrt(Utilities::MPI::sum(norm_squared, communicator));
    }

    /** @brief Minus the load at the owned DoFs of the system: it enters the
     *  balance through the internal force (before its compress()). */
    void
    subtract_from(NodalVector &internal_force) const
    {
      for (unsigned int i = 0; i < load.locally_owned_size(); ++i)
        if (in_system[i])
          internal_force.local_element(i) -= load.local_element(i);
    }

    /** @brief Its work over the displacement @p increment at this
     *  process's owned DoFs of the system. */
    double
    work(const NodalVector &increment) const
    {
      double sum = 0.;
      for (unsigned int i = 0; i < load.locally_owned_size(); ++i)
        if (in_system[i])
          sum += load.local_element(i) * increment.local_element(i);
      return sum;
    }

    /** @brief Its norm over the system's DoFs. */
    double
    norm() const
    {
      return load_norm;
    }

    /** @brief Its sum over the system's DoFs, per component. */
    const Tensor<1, dim> &
    sum() const
    {
      return total;
    }

  private:
    NodalVector       load;
    std::vector<bool> in_system;
    Tensor<1, dim>    total;
    double            load_norm = 0.;
  };
} // namespace impm

#endif
