#ifndef impm_core_point_properties_h
#define impm_core_point_properties_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

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
    /** First of the friction tractions of the domain's faces (dim per
     *  face, 2 dim faces), if the scene has a rigid body with friction. */
    unsigned int contact_traction = absent;
    /** Number of properties per point. */
    unsigned int n_properties = 0;

    /**
     * @brief Lay out the optional properties after the @p n_fixed ones
     * (@p n_contact_tractions: the friction tractions' entries, or 0).
     */
    void
    initialize(const unsigned int n_fixed,
               const bool         plastic,
               const bool         several_bodies,
               const unsigned int n_contact_tractions = 0)
    {
      n_properties       = n_fixed;
      plastic_multiplier = plastic ? n_properties++ : absent;
      body               = several_bodies ? n_properties++ : absent;
      contact_traction   = n_contact_tractions > 0 ? n_properties : absent;
      n_properties += n_contact_tractions;
    }
  };

  /**
   * @brief Typed read access to one material point's properties: the one
   * place that knows how tensors are stored in the property array.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class PointState
  {
  public:
    /** The property indices. */
    using P = PointProperties<dim>;

    /** @brief View the properties @p properties of one point. */
    explicit PointState(const dealii::ArrayView<const double> &properties)
      : properties(properties)
    {}

    /** @brief The initial position X. */
    dealii::Point<dim>
    initial_position() const
    {
      dealii::Point<dim> X;
      for (unsigned int d = 0; d < dim; ++d)
        X[d] = properties[P::initial_position + d];
      return X;
    }

    /** @brief The deformation gradient F (3x3, also in plane strain). */
    dealii::Tensor<2, 3>
    deformation_gradient() const
    {
      dealii::Tensor<2, 3> F;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          F[i][j] = properties[P::deformation_gradient + 3 * i + j];
      return F;
    }

    /** @brief J = det F. */
    double
    jacobian() const
    {
      return dealii::determinant(deformation_gradient());
    }

    /** @brief The elastic left Cauchy-Green tensor b^e. */
    dealii::SymmetricTensor<2, 3>
    elastic_left_cauchy_green() const
    {
      return symmetric(P::elastic_left_cauchy_green);
    }

    /** @brief The Kirchhoff stress tau. */
    dealii::SymmetricTensor<2, 3>
    kirchhoff_stress() const
    {
      return symmetric(P::kirchhoff_stress);
    }

    /** @brief The Cauchy stress sigma = tau / J. */
    dealii::SymmetricTensor<2, 3>
    cauchy_stress() const
    {
      return kirchhoff_stress() / jacobian();
    }

    /** @brief The initial volume V^0. */
    double
    initial_volume() const
    {
      return properties[P::initial_volume];
    }

    /** @brief The current volume J V^0. */
    double
    volume() const
    {
      return jacobian() * initial_volume();
    }

    /** @brief The mass. */
    double
    mass() const
    {
      return properties[P::mass];
    }

    /** @brief The current GIMP domain half-lengths. */
    dealii::Tensor<1, dim>
    domain_half_length() const
    {
      dealii::Tensor<1, dim> half_length;
      for (unsigned int d = 0; d < dim; ++d)
        half_length[d] = properties[P::domain_half_length + d];
      return half_length;
    }

  private:
    /** A symmetric tensor stored as its six unrolled entries. */
    dealii::SymmetricTensor<2, 3>
    symmetric(const unsigned int first) const
    {
      dealii::SymmetricTensor<2, 3> t;
      for (unsigned int k = 0; k < 6; ++k)
        t.access_raw_entry(k) = properties[first + k];
      return t;
    }

    /** The point's properties. */
    const dealii::ArrayView<const double> properties;
  };

  /**
   * @brief Typed write access to one material point's properties.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class MutablePointState : public PointState<dim>
  {
  public:
    /** The property indices. */
    using P = PointProperties<dim>;

    /** @brief View the properties @p properties of one point. */
    explicit MutablePointState(const dealii::ArrayView<double> &properties)
      : PointState<dim>(
          dealii::ArrayView<const double>(properties.data(), properties.size()))
      , properties(properties)
    {}

    /** @brief Set the deformation gradient F. */
    void
    set_deformation_gradient(const dealii::Tensor<2, 3> &F) const
    {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          properties[P::deformation_gradient + 3 * i + j] = F[i][j];
    }

    /** @brief Set the elastic left Cauchy-Green tensor b^e. */
    void
    set_elastic_left_cauchy_green(
      const dealii::SymmetricTensor<2, 3> &elastic_strain) const
    {
      set_symmetric(elastic_strain, P::elastic_left_cauchy_green);
    }

    /** @brief Set the Kirchhoff stress tau. */
    void
    set_kirchhoff_stress(const dealii::SymmetricTensor<2, 3> &tau) const
    {
      set_symmetric(tau, P::kirchhoff_stress);
    }

    /** @brief Set the current GIMP domain half-length in direction @p d. */
    void
    set_domain_half_length(const unsigned int d, const double value) const
    {
      properties[P::domain_half_length + d] = value;
    }

  private:
    /** Store a symmetric tensor as its six unrolled entries. */
    void
    set_symmetric(const dealii::SymmetricTensor<2, 3> &t,
                  const unsigned int                   first) const
    {
      for (unsigned int k = 0; k < 6; ++k)
        properties[first + k] = t.access_raw_entry(k);
    }

    /** The point's properties. */
    const dealii::ArrayView<double> properties;
  };
} // namespace impm

#endif
