#ifndef impm_simulator_material_test_h
#define impm_simulator_material_test_h

#include <deal.II/base/parameter_handler.h>

#include <impm/mechanics/material.h>

#include <ostream>
#include <string>
#include <vector>

namespace impm
{
  /**
   * @brief A material test without a grid: one material point of the
   * scene's first body's material driven along a strain or stress path
   * (the scene's top-level section `Material test`, enabled by its entry
   * `Enabled`). impm then runs the test instead of the scene and writes the
   * path to a CSV file.
   *
   * The point is a homogeneous sample whose axial direction is z (the
   * third axis, vertical as in a geostatic start), its lateral directions
   * x and y. It starts from the stress @f$\sigma_z = -\sigma_{v0}@f$,
   * @f$\sigma_x = \sigma_y = -K_0 \sigma_{v0}@f$ (the material's
   * elastic_strain_for_stress() and initialize_state(), as a geostatic
   * start), with the total deformation gradient F = I, and each step
   * calls the material's update() with the increment
   * @f$\Delta F = F_{n+1} F_n^{-1}@f$ and stores its state, as a point of
   * a scene does after a converged step. Strains are logarithmic and, like
   * the stresses written, compression positive:
   *
   * - drained triaxial compression or extension: the axial strain
   *   @f$\varepsilon_a = -\ln F_{zz}@f$ driven, the lateral strain
   *   @f$\ln F_{xx} = \ln F_{yy}@f$ found by Newton's method (the
   *   material's tangent) so that the lateral stress stays the cell
   *   pressure @f$K_0 \sigma_{v0}@f$;
   * - undrained triaxial compression or extension: isochoric,
   *   @f$\ln F_{xx} = \ln F_{yy} = -\ln F_{zz}/2@f$, so det F = 1 exactly
   *   at any strain;
   * - oedometer: only @f$F_{zz}@f$ changes;
   * - simple shear: @f$F = I + \gamma\, e_x \otimes e_z@f$;
   * - cyclic: one of the four above (`Cyclic path`), its driven strain a
   *   triangle wave 0, +A, 0, -A, 0 per cycle.
   */
  namespace MaterialTest
  {
    /** @brief The paths, in the order of their names. */
    enum class Path
    {
      drained_compression,
      drained_extension,
      undrained_compression,
      undrained_extension,
      oedometer,
      simple_shear,
      cyclic
    };

    /** @brief The entries of the section `Material test`. */
    struct Parameters
    {
      /** Whether impm runs the material test instead of the scene. */
      bool enabled = false;
      /** The path. */
      Path path = Path::drained_compression;
      /** For a cyclic path: the path whose strain cycles (not cyclic). */
      Path cyclic_path = Path::undrained_compression;
      /** The final axial or shear strain's magnitude, or the amplitude. */
      double strain = 0.1;
      /** The number of steps (per cycle on a cyclic path). */
      unsigned int n_steps = 100;
      /** The number of cycles of a cyclic path. */
      unsigned int n_cycles = 1;
      /** The initial vertical (axial) stress, compression positive, Pa. */
      double vertical_stress = 1e5;
      /** The ratio of the initial lateral to vertical stress. */
      double k0 = 1.;
      /** Whether the held and written stresses are Kirchhoff's. */
      bool kirchhoff = false;
      /** The CSV file (relative to the working directory). */
      std::string file = "material_test.csv";

      /** @brief Declare the section `Material test` and its entries. */
      static void
      declare_parameters(ParameterHandler &prm);

      /** @brief Read and check them (a bad value names its entry). */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /**
     * @brief One row of the CSV: the state after a step (step 0: the
     * start), compression positive, stresses in the chosen measure.
     */
    struct Row
    {
      /** The step. */
      unsigned int step = 0;
      /** Axial logarithmic strain @f$-\ln F_{zz}@f$. */
      double axial_strain = 0.;
      /** Shear strain @f$\gamma = F_{xz}@f$. */
      double shear_strain = 0.;
      /** Volumetric strain @f$-\ln \det F@f$. */
      double volumetric_strain = 0.;
      /** Mean effective stress p'. */
      double p = 0.;
      /** Deviatoric stress @f$q = \sqrt{3 J_2}@f$. */
      double q = 0.;
      /** Principal stresses, @f$\sigma_1 \ge \sigma_2 \ge \sigma_3@f$. */
      double principal[3] = {0., 0., 0.};
      /** The shear stress @f$\sigma_{xz}@f$ (positive with @f$\gamma@f$). */
      double shear_stress = 0.;
      /** The void ratio (NaN if the material has none). */
      double void_ratio = 0.;
      /** The material's state fields. */
      std::vector<double> state;
    };

    /**
     * @brief Drive one point of @p material along the path of @p
     * parameters.
     * @return The rows, the start first.
     */
    std::vector<Row>
    drive(const Material &material, const Parameters &parameters);

    /** @brief Whether the scene held by @p prm enables the test. */
    bool
    enabled(ParameterHandler &prm);

    /**
     * @brief Run the test the scene held by @p prm asks for: create the
     * material of `Body 1`, drive it, write the CSV file and print a
     * summary to @p out (the material, the path, the start and the end).
     */
    void
    run(ParameterHandler &prm, std::ostream &out);
  } // namespace MaterialTest
} // namespace impm

#endif
