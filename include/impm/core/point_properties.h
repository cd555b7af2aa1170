#ifndef impm_core_point_properties_h
#define impm_core_point_properties_h

namespace impm
{
  /**
   * @brief Where each quantity of a material point is stored in its
   * property array (Particles::ParticleHandler properties).
   *
   * Tensors of the deformation are 3x3 in 2D too (plane strain); symmetric
   * ones are stored as the six independent entries in deal.II's unrolled
   * order (xx, yy, zz, xy, xz, yz).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  struct PointProperties
  {
    /** The property indices. */
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
      /** Accumulated plastic multiplier (sum of the steps' increments). */
      plastic_multiplier = initial_domain_half_length + dim,
      /** Number of properties. */
      n_properties = plastic_multiplier + 1
    };
  };
} // namespace impm

#endif
