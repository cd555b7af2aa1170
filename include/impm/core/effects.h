#ifndef impm_core_effects_h
#define impm_core_effects_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <impm/base/plugin_list.h>
#include <impm/basis/basis_functions.h>
#include <impm/core/body.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief What a force effect may know of a material point.
   */
  template <int dim>
  struct MaterialPointInfo
  {
    /** Global id. */
    std::uint64_t id;
    /** Initial position X. */
    Point<dim> initial_position;
    /** Index of the point's body (0-based). */
    unsigned int body;
    /** Mass. */
    double mass;
  };

  /**
   * @brief A force on one face of a material point's domain: the share of
   * a traction that the point's boundary face carries. The assembler
   * spreads it with BasisEvaluator::face_weights().
   */
  template <int dim>
  struct FaceForce
  {
    /** Index of the point in the solver's order. */
    unsigned int point;
    /** Normal direction of the face. */
    unsigned int axis;
    /** Side of the face, +1 or -1. */
    double sign;
    /** The force. */
    Tensor<1, dim> force;
  };

  /**
   * @brief A physical effect that loads the material points: gravity, point
   * loads, tractions. Each is a class with its own parameter subsection,
   * registered by name; a scene switches it on with `Enabled = true` in that
   * subsection, and an effect that is off is never created, so it costs
   * nothing.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class ForceEffect
  {
  public:
    /** Destructor. */
    virtual ~ForceEffect() = default;

    /**
     * @brief Called once, on every process, after the points exist.
     * @param points This process's points.
     * @param bodies The scene's bodies.
     * @param grid The background grid.
     * @param communicator The processes of the run.
     */
    virtual void
    initialize(const std::vector<MaterialPointInfo<dim>> &points,
               const std::vector<Body<dim>>              &bodies,
               const CartesianGrid<dim>                  &grid,
               const MPI_Comm                             communicator);

    /**
     * @brief Add this effect's force on each point at @p load_factor (the
     * force reached at load factor 1, scaled linearly).
     * @param points This process's points, in the solver's order.
     * @param load_factor Between 0 and 1.
     * @param[in,out] forces One force per point, to add to.
     */
    virtual void
    add_forces(const std::vector<MaterialPointInfo<dim>> &points,
               const double                               load_factor,
               std::vector<Tensor<1, dim>>               &forces) const;

    /**
     * @brief Add this effect's forces on faces of the points' domains at
     * @p load_factor (tractions); none by default.
     * @param points This process's points, in the solver's order.
     * @param load_factor Between 0 and 1.
     * @param[in,out] face_forces The list to append to.
     */
    virtual void
    add_face_forces(const std::vector<MaterialPointInfo<dim>> &points,
                    const double                               load_factor,
                    std::vector<FaceForce<dim>> &face_forces) const;

    /**
     * @brief A one-line description with the parameters.
     */
    virtual std::string
    description() const = 0;

    /**
     * @brief The acceleration of a body force this effect applies in full
     * from the first load step on (not ramped): what a geostatic start is
     * in equilibrium with. Zero for every effect but an unramped gravity.
     */
    virtual Tensor<1, dim>
    acceleration_from_the_start() const
    {
      return Tensor<1, dim>();
    }

    /**
     * @brief Whether the forces change with the load factor. True by
     * default (always safe); an effect whose forces do not (an unramped
     * gravity) says false, and a step whose every effect says so assembles
     * the external force once for its start and its end.
     */
    virtual bool
    scales_with_load_factor() const
    {
      return true;
    }
  };

  /**
   * @brief The force effects, registered by name. An entry's
   * declare_parameters() declares `Enabled` (with the effect's default) and
   * the effect's own entries, in the subsection of its name.
   */
  template <int dim>
  using ForceEffectList = PluginList<ForceEffect<dim>, ParameterHandler &>;

  /**
   * @brief The scene's side of the force effects: one subsection each.
   */
  namespace EffectRegistry
  {
    /**
     * @brief Declare one subsection per registered effect, each with
     * `Enabled` and the effect's own entries.
     */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief Declare the `Enabled` entry of an effect, on by default or not.
     */
    void
    declare_enabled(ParameterHandler &prm, const bool enabled_by_default);

    /**
     * @brief Create the effects the scene enables, in the order of their
     * names.
     */
    template <int dim>
    std::vector<std::unique_ptr<ForceEffect<dim>>>
    create_enabled(ParameterHandler &prm);
  } // namespace EffectRegistry
} // namespace impm

/**
 * Register force effect CLASS (a class template over dim) under NAME, enabled
 * by default or not: the one line an effect needs besides its class.
 */
#define IMPM_REGISTER_FORCE_EFFECT(CLASS, NAME, ENABLED)   \
  IMPM_REGISTER_PLUGIN_IN_BOTH_DIMENSIONS(                 \
    impm::ForceEffectList,                                 \
    CLASS,                                                 \
    NAME,                                                  \
    ([](dealii::ParameterHandler &prm) {                   \
      impm::EffectRegistry::declare_enabled(prm, ENABLED); \
      CLASS<dim>::declare_parameters(prm);                 \
    }),                                                    \
    ([](dealii::ParameterHandler &prm)                     \
       -> std::unique_ptr<impm::ForceEffect<dim>> {        \
      return std::make_unique<CLASS<dim>>(prm);            \
    }))

#endif
