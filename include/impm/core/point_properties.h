#ifndef impm_core_point_properties_h
#define impm_core_point_properties_h

#include <limits>

namespace impm
{
  /**
   * @brief Where each quantity of a material point is stored in its
   * property array (Particles::ParticleHandler properties).
   *
   * Tensors of the deformation are 3x3 in 2D too (plane strain); symmetric
   * ones are stored as the six independent entries in deal.II's unrolled
   * order (xx, yy, zz, xy, xz, yz). The properties every scene needs come
   * first, in the enum; those only some scenes need (the plastic state of a
   * plastic material, the body index of a scene with several bodies) follow
   * in the order of PointLayout, and exist only when the scene asks for
   * them.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  struct PointProperties
  {
    /** The property indices every point has. */
    enum : unsigned int
    {
      /** Initial position X (dim entries). */
      initial_position = 0,
      /** Deformation gradient F, 3x3, row by row (9 entries). */
      deformation_gradient = initial_position + dim,
      /** Elastic left Cauchy-Green tensor b^e (6 entries). */
      elastic_left_cauchy_green = deformation_gradient + 9,
      /** Kirchhoff stress tau (6 entries). */
      kirchhoff_stress = elastic_left_cauchy_green + 6,
      /** Initial volume V^0. */
      initial_volume = kirchhoff_stress + 6,
      /** Mass m = rho_0 V^0. */
      mass = initial_volume + 1,
      /** Current GIMP domain half-lengths (dim entries). */
      domain_half_length = mass + 1,
      /** Initial GIMP domain half-lengths (dim entries). */
      initial_domain_half_length = domain_half_length + dim,
      /** Number of properties every point has. */
      n_fixed_properties = initial_domain_half_length + dim
    };
  };

  /**
   * @brief The optional properties of a scene's points and the total count.
   */
  struct PointLayout
  {
    /** Marks a property the scene does not store. */
    static constexpr unsigned int absent =
      std::numeric_limits<unsigned int>::max();

    /** Accumulated plastic multiplier, if any body is plastic. */
    unsigned int plastic_multiplier = absent;
    /** Index of the point's body, if the scene has several. */
    unsigned int body = absent;
    /** Number of properties per point. */
    unsigned int n_properties = 0;

    /**
     * @brief Lay out the optional properties after the @p n_fixed ones.
     */
    void
    initialize(const unsigned int n_fixed,
               const bool         plastic,
               const bool         several_bodies)
    {
      n_properties       = n_fixed;
      plastic_multiplier = plastic ? n_properties++ : absent;
      body               = several_bodies ? n_properties++ : absent;
    }
  };
} // namespace impm

#endif
