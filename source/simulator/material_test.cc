// The material test without a grid: one point driven along a path.
#include <deal.II/base/exceptions.h>

#include <impm/base/errors.h>
#include <impm/mechanics/modified_cam_clay.h>
#include <impm/simulator/material_test.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace impm
{
  namespace MaterialTest
  {
    namespace
    {
      /** The names of the paths, in enum order. */
      const std::vector<std::string> path_names = {
        "drained triaxial compression",
        "drained triaxial extension",
        "undrained triaxial compression",
        "undrained triaxial extension",
        "oedometer",
        "simple shear",
        "cyclic"};

      /** The names of the paths a cyclic path may cycle. */
      const std::vector<std::string> cyclic_names = {"drained triaxial",
                                                     "undrained triaxial",
                                                     "oedometer",
                                                     "simple shear"};

      /** @p names joined by '|', a Patterns::Selection. */
      std::string
      selection(const std::vector<std::string> &names)
      {
        std::string joined;
        for (const auto &name : names)
          joined += (joined.empty() ? "" : "|") + name;
        return joined;
      }

      /**
       * The driven strain after step @p k: monotonic, signed (negative
       * axial strain in extension), or the triangle wave of a cyclic path.
       */
      double
      driven_strain(const Parameters &parameters, const unsigned int k)
      {
        const double t = double(k) / parameters.n_steps;
        if (parameters.path != Path::cyclic)
          {
            const bool extension = parameters.path == Path::drained_extension ||
                                   parameters.path == Path::undrained_extension;
            return (extension ? -1. : 1.) * parameters.strain * t;
          }
        const double phase = t - std::floor(t);
        const double wave  = phase < 0.25 ? 4. * phase :
                             phase < 0.75 ? 2. - 4. * phase :
                                            4. * phase - 4.;
        return parameters.strain * wave;
      }

      /**
       * The total deformation gradient for the driven strain @p x and the
       * lateral logarithmic strain @p lateral (drained paths only).
       */
      Tensor<2, 3>
      deformation(const Path path, const double x, const double lateral)
      {
        Tensor<2, 3> F = unit_symmetric_tensor<3>();
        switch (path)
          {
            case Path::drained_compression:
            case Path::drained_extension:
              F[0][0] = F[1][1] = std::exp(lateral);
              F[2][2]           = std::exp(-x);
              break;
            case Path::undrained_compression:
            case Path::undrained_extension:
              F[0][0] = F[1][1] = std::exp(x / 2.);
              F[2][2]           = std::exp(-x);
              break;
            case Path::oedometer:
              F[2][2] = std::exp(-x);
              break;
            case Path::simple_shear:
              F[0][2] = x;
              break;
            default:
              Assert(false, ExcInternalError());
          }
        return F;
      }

      /** The stress in the chosen measure, tension positive. */
      SymmetricTensor<2, 3>
      stress(const ConstitutiveUpdate &result,
             const double              J,
             const bool                kirchhoff)
      {
        return kirchhoff ? result.kirchhoff_stress :
                           result.kirchhoff_stress / J;
      }
    } // namespace



    void
    Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material test");
      prm.declare_entry(
        "Enabled",
        "false",
        Patterns::Bool(),
        "Run a material test instead of the scene: one material point of "
        "Body 1's material (its parameters as in the scene) driven along "
        "'Path' without a grid, written to 'File'. Axial is z; strains are "
        "logarithmic and stresses written compression positive.");
      prm.declare_entry(
        "Path",
        path_names[0],
        Patterns::Selection(selection(path_names)),
        "drained triaxial: the axial strain driven, the lateral stress held "
        "at the cell pressure K0 * 'Initial vertical stress' (Newton's "
        "method on the lateral strain); undrained triaxial: isochoric, "
        "lateral log strain = -axial/2 (det F = 1 exactly); oedometer: "
        "axial strain only; simple shear: F = I + gamma e_x (x) e_z; "
        "cyclic: the strain of 'Cyclic path' as a triangle wave of "
        "amplitude 'Strain'.");
      prm.declare_entry("Cyclic path",
                        cyclic_names[1],
                        Patterns::Selection(selection(cyclic_names)),
                        "The path a cyclic test cycles (its compression "
                        "half first).");
      prm.declare_entry("Strain",
                        "0.1",
                        Patterns::Double(0., 10.),
                        "The final axial logarithmic strain's magnitude "
                        "(triaxial, oedometer), the final shear strain "
                        "gamma (simple shear), or the amplitude (cyclic); "
                        "> 0.");
      prm.declare_entry("Number of steps",
                        "100",
                        Patterns::Integer(1, 10000000),
                        "Steps of the path (per cycle on a cyclic path, "
                        "then a multiple of 4, so that the peaks are steps). "
                        "A step the model cannot take is taken again in 2, "
                        "4, ... 64 sub-steps; the file has a row per step.");
      prm.declare_entry("Number of cycles",
                        "1",
                        Patterns::Integer(1, 100000),
                        "Cycles of a cyclic path.");
      prm.declare_entry("Initial vertical stress",
                        "1e5",
                        Patterns::Double(0.),
                        "The initial axial stress sigma_v0 in Pa, "
                        "compression positive (> 0).");
      prm.declare_entry("K0",
                        "1",
                        Patterns::Double(0.),
                        "The initial lateral stress over the vertical one "
                        "(> 0; 1: isotropic); the cell pressure of a drained "
                        "triaxial path is K0 sigma_v0.");
      prm.declare_entry("Stress measure",
                        "Cauchy",
                        Patterns::Selection("Cauchy|Kirchhoff"),
                        "The measure of the held cell pressure and of the "
                        "stresses written: Cauchy's (a real cell) or "
                        "Kirchhoff's (J times Cauchy's: the measure the "
                        "models are stated in).");
      prm.declare_entry("File",
                        "material_test.csv",
                        Patterns::Anything(),
                        "The CSV file written, relative to the working "
                        "directory: step, axial_strain, shear_strain, "
                        "volumetric_strain, p, q, sigma_1, sigma_2, sigma_3, "
                        "shear_stress, void_ratio (a material with one), then "
                        "the material's state fields.");
      prm.leave_subsection();
    }



    void
    Parameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material test");
      enabled = prm.get_bool("Enabled");
      path =
        Path(std::find(path_names.begin(), path_names.end(), prm.get("Path")) -
             path_names.begin());
      const std::string cyclic = prm.get("Cyclic path");
      cyclic_path = cyclic == "drained triaxial" ? Path::drained_compression :
                    cyclic == "undrained triaxial" ?
                                                   Path::undrained_compression :
                    cyclic == "oedometer" ? Path::oedometer :
                                            Path::simple_shear;
      strain      = prm.get_double("Strain");
      n_steps     = prm.get_integer("Number of steps");
      n_cycles    = prm.get_integer("Number of cycles");
      vertical_stress   = prm.get_double("Initial vertical stress");
      k0                = prm.get_double("K0");
      kirchhoff         = prm.get("Stress measure") == "Kirchhoff";
      file              = prm.get("File");
      const auto refuse = [&](const std::string &entry,
                              const std::string &why) {
        const std::string value = prm.get(entry);
        prm.leave_subsection();
        throw InputError("Parameter 'Material test/" + entry + "' = '" + value +
                         "' is not allowed: " + why);
      };
      for (const char *entry : {"Strain", "Initial vertical stress", "K0"})
        if (!(prm.get_double(entry) > 0.))
          refuse(entry, "it must be > 0.");
      if (path == Path::cyclic && n_steps % 4 != 0)
        refuse("Number of steps",
               "a cyclic path needs a multiple of 4 steps per cycle.");
      if (file.empty())
        refuse("File", "the material test needs a file to write.");
      prm.leave_subsection();
    }



    namespace
    {
      /**
       * Why a step's row leaves what floating point holds or what the
       * model describes (empty if it does not).
       */
      std::string
      row_problem(const Row &row)
      {
        if (!std::isfinite(row.p) || !std::isfinite(row.q))
          return "the stress is not finite (p' = " + number_text(row.p) +
                 " Pa, q = " + number_text(row.q) +
                 " Pa): the path leaves what floating point holds; take a "
                 "smaller strain or stress.";
        if (row.void_ratio <= 0.)
          return "the void ratio fell to " + number_text(row.void_ratio) +
                 " at p' = " + number_text(row.p) +
                 " Pa: the model's compression lines hold no state beyond a "
                 "void ratio of 0; take a smaller strain or stress.";
        return "";
      }

      /** The one line that ends the test at step @p k of @p n_steps. */
      CollectiveError
      step_failure(const Parameters  &parameters,
                   const unsigned int n_steps,
                   const unsigned int k,
                   const std::string &what)
      {
        std::ostringstream message;
        message << "Material test: step " << k << " of " << n_steps
                << " (driven strain " << driven_strain(parameters, k)
                << "): " << what;
        return CollectiveError(message.str());
      }
    } // namespace



    std::vector<Row>
    drive(const Material &material, const Parameters &parameters)
    {
      const Path path = parameters.path == Path::cyclic ?
                          parameters.cyclic_path :
                          parameters.path;
      const bool drained =
        path == Path::drained_compression || path == Path::drained_extension;
      const double       cell = parameters.k0 * parameters.vertical_stress;
      const unsigned int n_steps =
        parameters.n_steps *
        (parameters.path == Path::cyclic ? parameters.n_cycles : 1);

      SymmetricTensor<2, 3> tau;
      tau[0][0] = tau[1][1]    = -cell;
      tau[2][2]                = -parameters.vertical_stress;
      SymmetricTensor<2, 3> be = material.elastic_strain_for_stress(tau);
      std::vector<double>   state(material.n_state_entries());
      material.initialize_state(tau, make_array_view(state));
      const auto  *clay = dynamic_cast<const ModifiedCamClay *>(&material);
      const double e0   = clay != nullptr ?
                            clay->initial_void_ratio() :
                            std::numeric_limits<double>::quiet_NaN();

      Tensor<2, 3>     F       = unit_symmetric_tensor<3>();
      double           lateral = 0.;
      std::vector<Row> rows;
      const auto       record = [&](const unsigned int        step,
                              const ConstitutiveUpdate &result) {
        const double J     = determinant(F);
        const auto   sigma = stress(result, J, parameters.kirchhoff);
        Row          row;
        row.step              = step;
        row.axial_strain      = std::log(1. / F[2][2]);
        row.shear_strain      = F[0][2];
        row.volumetric_strain = std::log(1. / J);
        row.p                 = -trace(sigma) / 3.;
        row.q                 = std::sqrt(1.5) * deviator(sigma).norm();
        const auto eigen      = eigenvalues(sigma);
        for (unsigned int a = 0; a < 3; ++a)
          row.principal[a] = -eigen[2 - a];
        row.shear_stress = sigma[0][2];
        row.void_ratio   = (1. + e0) * J - 1.;
        row.state        = state;
        rows.push_back(row);
      };
      ConstitutiveUpdate start;
      start.kirchhoff_stress = tau;
      record(0, start);

      // One step of the path to the driven strain x: the update (with the
      // lateral strain that holds the cell pressure on a drained path),
      // then the new elastic strain and state.
      ConstitutiveUpdate result;
      const auto         advance = [&](const double x) {
        const Tensor<2, 3> F_n_inverse = invert(F);
        const auto         update = [&](const double lateral_strain) {
          F = deformation(path, x, lateral_strain);
          material.update(F * F_n_inverse,
                          be,
                          make_array_view(std::as_const(state)),
                          result);
          return stress(result, determinant(F), parameters.kirchhoff)[0][0] +
                 cell;
        };
        double residual = update(lateral);
        for (unsigned int iteration = 0;
             drained && std::abs(residual) > 1e-11 * cell;
             ++iteration)
          {
            if (iteration == 50)
              throw CollectiveError(
                "the lateral stress did not converge in 50 Newton "
                        "iterations.");
            // d tau = C : G with G = diag(1, 1, 0) per unit lateral
            // strain; Cauchy's stress tau/J with dJ/J = 2.
            Tensor<4, 3> C;
            material.tangent(result, 3, C);
            const double J     = determinant(F);
            double       slope = C[0][0][0][0] + C[0][0][1][1];
            if (!parameters.kirchhoff)
              slope = slope / J - 2. * result.kirchhoff_stress[0][0] / J;
            double step = -residual / slope;
            // Halve the step while the residual grows.
            for (unsigned int halving = 0;; ++halving)
              {
                const double trial = update(lateral + step);
                if (std::abs(trial) < std::abs(residual) || halving == 30)
                  {
                    lateral += step;
                    residual = trial;
                    break;
                  }
                step /= 2.;
              }
          }
        be = result.elastic_left_cauchy_green;
        material.store_state(result, make_array_view(state));
      };
      for (unsigned int k = 1; k <= n_steps; ++k)
        {
          // A step the model cannot take (a return that fails, a lateral
          // stress that does not converge) is taken again in 2, 4, ... 64
          // sub-steps from the same state; only the whole step is written.
          const double       x_start = driven_strain(parameters, k - 1);
          const double       x_end   = driven_strain(parameters, k);
          const Tensor<2, 3> F_start = F;
          const SymmetricTensor<2, 3> be_start      = be;
          const std::vector<double>   state_start   = state;
          const double                lateral_start = lateral;
          std::string                 why;
          bool                        done = false;
          for (unsigned int n_sub = 1; n_sub <= 64 && !done; n_sub *= 2)
            {
              F       = F_start;
              be      = be_start;
              state   = state_start;
              lateral = lateral_start;
              try
                {
                  for (unsigned int s = 1; s <= n_sub; ++s)
                    advance(x_start + (x_end - x_start) * s / n_sub);
                  done = true;
                }
              catch (const ExceptionBase &exception)
                {
                  std::ostringstream info;
                  exception.print_info(info);
                  why = collapse_white_space(info.str());
                }
              catch (const CollectiveError &error)
                {
                  why = error.what();
                }
            }
          if (!done)
            throw step_failure(parameters,
                               n_steps,
                               k,
                               "the material's update failed, in one step and "
                               "in up to 64 sub-steps: " +
                                 why);
          record(k, result);
          if (const std::string problem = row_problem(rows.back());
              !problem.empty())
            throw step_failure(parameters, n_steps, k, problem);
        }
      return rows;
    }



    bool
    enabled(ParameterHandler &prm)
    {
      prm.enter_subsection("Material test");
      const bool on = prm.get_bool("Enabled");
      prm.leave_subsection();
      return on;
    }



    void
    run(ParameterHandler &prm, std::ostream &out)
    {
      Parameters parameters;
      parameters.parse_parameters(prm);
      prm.enter_subsection("Body 1");
      prm.enter_subsection("Material");
      std::unique_ptr<Material> material;
      try
        {
          material = MaterialRegistry::create(prm, "Body 1/Material");
        }
      catch (...)
        {
          prm.leave_subsection();
          prm.leave_subsection();
          throw;
        }
      prm.leave_subsection();
      prm.leave_subsection();

      const std::vector<Row> rows = drive(*material, parameters);

      std::vector<std::string> state_names;
      for (const auto &field : material->state_fields())
        for (unsigned int c = 0; c < field.n_components; ++c)
          state_names.push_back(field.n_components == 1 ?
                                  field.name :
                                  field.name + "_" + std::to_string(c));
      const bool    has_void_ratio = std::isfinite(rows[0].void_ratio);
      std::ofstream csv(parameters.file);
      if (!csv)
        throw InputError("Material test: cannot write the file '" +
                         parameters.file + "' ('Material test/File').");
      csv << "step,axial_strain,shear_strain,volumetric_strain,p,q,sigma_1,"
             "sigma_2,sigma_3,shear_stress"
          << (has_void_ratio ? ",void_ratio" : "");
      for (const auto &name : state_names)
        csv << ',' << name;
      csv << '\n' << std::setprecision(12);
      for (const Row &row : rows)
        {
          csv << row.step << ',' << row.axial_strain << ',' << row.shear_strain
              << ',' << row.volumetric_strain << ',' << row.p << ',' << row.q
              << ',' << row.principal[0] << ',' << row.principal[1] << ','
              << row.principal[2] << ',' << row.shear_stress;
          if (has_void_ratio)
            csv << ',' << row.void_ratio;
          for (const double value : row.state)
            csv << ',' << value;
          csv << '\n';
        }
      csv.close();
      if (!csv)
        throw InputError("Material test: writing the file '" + parameters.file +
                         "' failed.");

      prm.enter_subsection("Material test");
      const std::string path_name = prm.get("Path");
      const std::string cyclic    = prm.get("Cyclic path");
      prm.leave_subsection();
      out << "Material test: " << material->description() << '\n'
          << "path: " << path_name
          << (parameters.path == Path::cyclic ?
                " (" + cyclic + ", " + std::to_string(parameters.n_cycles) +
                  " cycles)" :
                std::string())
          << ", " << rows.size() - 1 << " steps, stresses "
          << (parameters.kirchhoff ? "Kirchhoff" : "Cauchy") << ", written to "
          << parameters.file << '\n';
      out << std::setprecision(8);
      for (const Row *row : {&rows.front(), &rows.back()})
        out << "step " << row->step << ": axial strain " << row->axial_strain
            << ", shear strain " << row->shear_strain << ", volumetric strain "
            << row->volumetric_strain << ", p' " << row->p << ", q " << row->q
            << '\n';
    }
  } // namespace MaterialTest
} // namespace impm
