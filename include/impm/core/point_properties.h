#ifndef impm_core_point_properties_h
#define impm_core_point_properties_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <impm/base/point_field.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  /**
   * @brief Where each quantity of a material point is stored in its
   * property array (Particles::ParticleHandler properties).
   *
   * Tensors of the deformation are 3x3 in 2D too (plane strain); symmetric
   * ones are stored as the six independent entries in deal.II's unrolled
   * order (xx, yy, zz, xy, xz, yz). The properties every scene needs come
   * first, in the enum; those only some scenes need (the body index of a
   * scene with several bodies, the state its materials and couplings
   * declare) follow in the order of PointLayout, and exist only when the
   * scene asks for them.
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
   * @brief Where the optional properties of a scene's points are: those
   * the scene's description needs (the body index, with several bodies) and
   * those declared by whoever needs them (PointField): the state variables
   * of each body's material and the per-point history of the couplings.
   *
   * The properties follow the fixed ones of PointProperties: the body index
   * (if any), then one block of material state, then the couplings' fields
   * in the order declared. A point belongs to one body, so the bodies'
   * materials share the material-state block: it is as long as the longest
   * material's state, and each material sees its own fields at the start
   * of the block, in the order it declared them.
   */
  class PointLayout
  {
  public:
    /** Marks a property the scene does not store. */
    static constexpr unsigned int absent =
      std::numeric_limits<unsigned int>::max();

    /**
     * @brief A field the point files may write: its name, its number of
     * entries and, for each body, the index of its first entry (absent if
     * that body's points do not store it).
     */
    struct WrittenField
    {
      /** The field's name. */
      std::string name;
      /** Entries per point. */
      unsigned int n_components;
      /** The first entry's property index, per body (absent: not stored). */
      std::vector<unsigned int> first_by_body;
    };

    /**
     * @brief Lay out the optional properties after the @p n_fixed ones.
     * @param n_fixed The properties every point has.
     * @param material_fields The state fields of each body's material, by
     *   body (their number is the scene's number of bodies).
     * @param coupling_fields The fields the scene's couplings declare.
     * @throw std::logic_error If two declarations of one name differ in
     *   size or two couplings declare the same name (a plugin's mistake).
     */
    void
    initialize(const unsigned int              n_fixed,
               const std::vector<PointFields> &material_fields,
               const PointFields              &coupling_fields);

    /** @brief The number of properties per point. */
    unsigned int
    n_properties() const
    {
      return n_total;
    }

    /** @brief The property holding the body index, or absent (one body). */
    unsigned int
    body_index() const
    {
      return body;
    }

    /** @brief The first property of the material state block. */
    unsigned int
    material_state_first() const
    {
      return material_first;
    }

    /** @brief The number of state entries of body @p b's material. */
    unsigned int
    n_material_state(const unsigned int b) const
    {
      return material_sizes[b];
    }

    /**
     * @brief The first property of the coupling field @p name, or absent
     * if no coupling of the scene declared it.
     */
    unsigned int
    coupling_field(const std::string &name) const;

    /** @brief The entries of the coupling field @p name (0 if none). */
    unsigned int
    coupling_field_entries(const std::string &name) const;

    /** @brief The fields the point files may write, in declaration order. */
    const std::vector<WrittenField> &
    written_fields() const
    {
      return writable;
    }

    /**
     * @brief One line naming every optional property and its size, for the
     * checkpoint: a checkpoint resumes only into the same layout.
     */
    std::string
    description() const;

  private:
    /** The body index's property, or absent. */
    unsigned int body = absent;
    /** The first property of the material-state block. */
    unsigned int material_first = 0;
    /** Each body's material-state entries. */
    std::vector<unsigned int> material_sizes;
    /** Each body's material's fields (for the description). */
    std::vector<PointFields> material_declarations;
    /** The couplings' fields and their first properties. */
    std::vector<std::pair<PointField, unsigned int>> couplings;
    /** The fields the point files may write. */
    std::vector<WrittenField> writable;
    /** Number of properties per point. */
    unsigned int n_total = 0;
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
