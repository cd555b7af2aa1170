#ifndef impm_coupling_coupling_inputs_h
#define impm_coupling_coupling_inputs_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <impm/core/parameters.h>
#include <impm/grid/background_grid.h>

#include <string>

namespace impm
{
  using namespace dealii;

  /**
   * @brief What a coupling is created from: the scene, its parameter file
   * (for couplings that declare their own subsection) and the grid.
   */
  template <int dim>
  struct CouplingInputs
  {
    /** The scene. */
    const Parameters::All<dim> &parameters;
    /** The scene's parameter file. */
    ParameterHandler &prm;
    /** The background grid. */
    const BackgroundGrid<dim> &grid;
    /** The scene's time (subsection `Time`). */
    const Parameters::Time &time;
    /** The acceleration applied in full from the first step (an unramped
     *  gravity): the load at load factor 0. */
    Tensor<1, dim> acceleration_from_the_start;

    /** @brief Refuse an axisymmetric scene, naming @p coupling (one not
     *  yet formulated with the ring's 2 pi r). */
    void
    refuse_axisymmetry(const std::string &coupling) const;
  };
} // namespace impm

#endif
