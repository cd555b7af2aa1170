// Modified Cam-clay (ModifiedCamClay) driven at one point along the paths
// of the laboratory, against closed forms and an independent integration.
//
// Material: M = 1.2, lambda = 0.2, kappa = 0.04, e0 = 1 (v0 = 2, so
// lambda* = 0.1, kappa* = 0.02, lambda* - kappa* = 0.08), G = 3 MPa,
// p_ref = 100 kPa. Every sample starts at p0 = p_ref, q = 0 (b^e = I) with
// p_c0 = OCR p0. p and q are Kirchhoff stresses, compression positive;
// strains are logarithmic, compression positive; Kirchhoff is Cauchy times
// J = det F.
//
// (a) Isotropic compression, F = s I. On the normal compression line the
//     model's definition gives ln J = -lambda* ln(p/p0) exactly (the
//     exponential map adds the logarithmic elastic and plastic volume
//     changes; ln p is linear in the elastic one, ln p_c in the plastic
//     one): so ln v - ln p' is linear with slope -lambda*, checked to 1e-6
//     at steps of any size. On unloading ln J - ln J_max = -kappa*
//     ln(p/p_max). The slope of e - ln p' is lambda v/v0: lambda at e0
//     only (measured with a small step at the start and at the end).
// (b) Undrained (isochoric) triaxial compression, F = diag(s, 1/sqrt s,
//     1/sqrt s), of a normally consolidated sample, against p/p0 =
//     (M^2/(M^2 + eta^2))^Lambda, Lambda = (lambda - kappa)/lambda, from
//     the rate equations of Cam-clay: d eps_v = 0 = kappa* dp/p +
//     (lambda* - kappa*) dp_c/p_c with p_c = p (M^2 + eta^2)/M^2 on the
//     surface. It applies to this model at finite strain, at every step's
//     end and for any step size, because (1) J = 1, so Kirchhoff and
//     Cauchy stresses agree and the total logarithmic volume change is
//     zero; (2) the exponential map adds the logarithmic elastic and
//     plastic volume changes exactly; (3) p is exponential in the elastic
//     and p_c in the plastic volume change, the integrated forms of the
//     rate equations; (4) each plastic step ends on the surface; (5) the
//     sample starts on it (p_c0 = p0). Within 0.5 % (in fact to the
//     return's tolerance).
// (c) Drained triaxial compression of a normally consolidated sample: the
//     lateral Kirchhoff stress held at -p0 by a Newton loop on the lateral
//     stretch, the axial log strain in steps of 2e-4. Against the rate
//     equations integrated by scripts/cam_clay_drained.py (RK4; its table
//     is copied below), at q = 0.2 ... 0.98 q_cs, the model's step ends
//     interpolated linearly in p: axial and volumetric strain within
//     0.5 %. On this path the critical state is p_cs = 3 p0/(3 - M), q_cs =
//     M p_cs, approached asymptotically; its volume change is the closed
//     form lambda* ln(p_cs/p0) + (lambda* - kappa*) ln 2.
// (d) The same for OCR = 10: elastic to the yield point on the dry side
//     (p_y, q_y from a quadratic, in the script), then softening back along
//     the path towards the same critical state.
// (e) Hard cases: the tip of the ellipse (p = p_c, q = 0) loaded
//     isotropically, sheared and unloaded; very low mean stress (an
//     isotropic swelling by ln J = 0.3 to p = p0 exp(-15)), sheared; a
//     trial state that a Hencky law would put in tension (p stays > 0);
//     an expansion that underflows (an exception: a failed Newton
//     iteration). Each return is checked against its own equations,
//     recomputed here from the returned stress.

#include <deal.II/base/exceptions.h>

#include <impm/mechanics/modified_cam_clay.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <vector>

#include "tests.h"

using namespace impm;

namespace
{
  constexpr double p0 = 1e5;

  ModifiedCamClay::Parameters
  parameters(const double ocr)
  {
    ModifiedCamClay::Parameters p;
    p.critical_state_ratio    = 1.2;
    p.lambda                  = 0.2;
    p.kappa                   = 0.04;
    p.initial_void_ratio      = 1.;
    p.shear_modulus           = 3e6;
    p.reference_pressure      = p0;
    p.overconsolidation_ratio = ocr;
    return p;
  }

  /** One point under a diagonal deformation gradient. */
  struct Sample
  {
    Sample(const ModifiedCamClay &model, const double pressure)
      : model(model)
    {
      const SymmetricTensor<2, 3> stress =
        -pressure * unit_symmetric_tensor<3>();
      be = model.elastic_strain_for_stress(stress);
      model.initialize_state(stress, ArrayView<double>(&pc, 1));
      tau = stress;
    }

    /** The update to the total stretches @p s, not accepted. */
    ConstitutiveUpdate
    trial(const std::array<double, 3> &s) const
    {
      Tensor<2, 3> dF;
      for (unsigned int a = 0; a < 3; ++a)
        dF[a][a] = s[a] / stretch[a];
      ConstitutiveUpdate u;
      model.update(dF, be, ArrayView<const double>(&pc, 1), u);
      return u;
    }

    void
    accept(const std::array<double, 3> &s, const ConstitutiveUpdate &u)
    {
      be = u.elastic_left_cauchy_green;
      model.store_state(u, ArrayView<double>(&pc, 1));
      stretch = s;
      tau     = u.kirchhoff_stress;
    }

    void
    go_to(const std::array<double, 3> &s)
    {
      accept(s, trial(s));
    }

    double
    p() const
    {
      return ModifiedCamClay::mean_pressure(tau);
    }
    double
    q() const
    {
      return ModifiedCamClay::deviatoric_stress(tau);
    }
    double
    log_volume() const
    {
      return std::log(stretch[0] * stretch[1] * stretch[2]);
    }

    const ModifiedCamClay &model;
    SymmetricTensor<2, 3>  be;
    SymmetricTensor<2, 3>  tau;
    double                 pc      = 0.;
    std::array<double, 3>  stretch = {{1., 1., 1.}};
  };

  void
  print(const char *format, const double a, const double b = 0.)
  {
    char line[200];
    std::snprintf(line, sizeof(line), format, a, b);
    std::cout << line << std::endl;
  }

  void
  isotropic_compression()
  {
    const ModifiedCamClay model(parameters(1.));
    const double          lambda_star = model.modified_lambda();
    const double          kappa_star  = model.modified_kappa();
    std::cout << "(a) isotropic compression, normally consolidated"
              << std::endl;
    Sample sample(model, p0);
    // The slope of e - ln p' at e0, from a first small step.
    sample.go_to({{std::exp(-1e-7), std::exp(-1e-7), std::exp(-1e-7)}});
    print("  slope of e - ln p' at e = e0: %.6f (lambda = 0.2)",
          -2. * std::expm1(sample.log_volume()) / std::log(sample.p() / p0));
    double max_error = 0.;
    // Steps of growing size: 0.01, 0.02, ... in ln J.
    double ln_J = sample.log_volume();
    for (unsigned int step = 1; step <= 8; ++step)
      {
        ln_J -= 0.01 * step;
        const double s = std::exp(ln_J / 3.);
        sample.go_to({{s, s, s}});
        const double reference = -lambda_star * std::log(sample.p() / p0);
        max_error =
          std::max(max_error, std::abs(ln_J - reference) / std::abs(ln_J));
        if (step % 2 == 0)
          {
            print("  ln J = %.4f: p/p0 = %.8f", ln_J, sample.p() / p0);
            print("    p_c/p = %.10f, v = v0 J = %.8f",
                  sample.pc / sample.p(),
                  2. * std::exp(ln_J));
          }
      }
    impm_tests::check_below(
      "  ln J = -lambda* ln(p/p0) on the NCL, relative error", max_error, 1e-6);
    // The slope of e - ln p' at the end, from a small step: lambda v/v0.
    const double v_end = 2. * std::exp(sample.log_volume());
    {
      Sample       probe  = sample;
      const double s      = std::exp((sample.log_volume() - 3e-7) / 3.);
      const double p_then = sample.p();
      probe.go_to({{s, s, s}});
      print("  slope of e - ln p' at v = %.6f: %.6f",
            v_end,
            -(2. * std::exp(probe.log_volume()) - v_end) /
              std::log(probe.p() / p_then));
      print("    lambda v/v0 = %.6f", 0.2 * v_end / 2.);
    }
    // Unloading: elastic, ln J - ln J_max = -kappa* ln(p/p_max).
    const double ln_J_max = sample.log_volume(), p_max = sample.p();
    max_error = 0.;
    for (unsigned int step = 1; step <= 4; ++step)
      {
        const double s = std::exp((ln_J_max + 0.005 * step) / 3.);
        sample.go_to({{s, s, s}});
        const double predicted = -kappa_star * std::log(sample.p() / p_max);
        max_error =
          std::max(max_error,
                   std::abs(sample.log_volume() - ln_J_max - predicted) /
                     (0.005 * step));
      }
    print("  unloaded to p/p_max = %.8f", sample.p() / p_max);
    impm_tests::check_below("  swelling line ln J - ln J_max = -kappa* "
                            "ln(p/p_max), relative error",
                            max_error,
                            1e-6);
  }

  void
  undrained_compression()
  {
    const ModifiedCamClay model(parameters(1.));
    const double          M = 1.2, Lambda = (0.2 - 0.04) / 0.2;
    std::cout << "(b) undrained triaxial compression, normally consolidated"
              << std::endl;
    Sample sample(model, p0);
    double max_error = 0.;
    // Axial log strain to 0.3 in 300 steps.
    for (unsigned int step = 1; step <= 300; ++step)
      {
        const double s = std::exp(-0.001 * step);
        sample.go_to({{s, 1. / std::sqrt(s), 1. / std::sqrt(s)}});
        const double eta       = sample.q() / sample.p();
        const double reference = std::pow(M * M / (M * M + eta * eta), Lambda);
        const double error     = std::abs(sample.p() / p0 / reference - 1.);
        max_error              = std::max(max_error, error);
        if (step == 1 || step == 5 || step == 20 || step == 100 || step == 300)
          {
            print("  axial strain %.3f: eta/M = %.8f", 0.001 * step, eta / M);
            print("    p/p0 = %.8f, closed form %.8f",
                  sample.p() / p0,
                  reference);
          }
      }
    impm_tests::check_below(
      "  p/p0 against the closed form, largest relative error",
      max_error,
      5e-3);
    impm_tests::check_below("  (and below the return's tolerance)",
                            max_error,
                            1e-9);
    print("  q/(M p) at the end: %.6f", sample.q() / (M * sample.p()), 0.);
  }

  /** A drained step: the lateral Kirchhoff stress held at -p0. */
  void
  drained_step(Sample &sample, const double axial)
  {
    double       ln_r     = std::log(sample.stretch[1]);
    const double h        = 1e-8;
    const auto   residual = [&](const double x, ConstitutiveUpdate &u) {
      u = sample.trial({{axial, std::exp(x), std::exp(x)}});
      return (u.kirchhoff_stress[1][1] + p0) / p0;
    };
    ConstitutiveUpdate u;
    for (unsigned int iteration = 0; iteration < 50; ++iteration)
      {
        const double r = residual(ln_r, u);
        if (std::abs(r) < 1e-12)
          break;
        ConstitutiveUpdate plus, minus;
        const double       slope =
          (residual(ln_r + h, plus) - residual(ln_r - h, minus)) / (2. * h);
        ln_r -= r / slope;
        AssertThrow(iteration < 49, ExcMessage("lateral Newton failed"));
      }
    sample.accept({{axial, std::exp(ln_r), std::exp(ln_r)}}, u);
  }

  /** A state along the path: p, axial and volumetric strain. */
  struct PathPoint
  {
    double p, eps_a, eps_v;
  };

  /**
   * The model's strains at p/p0 = @p target, linear in p between the step
   * ends of @p path (the branch where p runs monotonically).
   */
  std::pair<double, double>
  at_pressure(const std::vector<PathPoint> &path, const double target)
  {
    for (unsigned int i = 1; i < path.size(); ++i)
      {
        const double a = path[i - 1].p / p0, b = path[i].p / p0;
        if ((a - target) * (b - target) <= 0. && a != b)
          {
            const double t = (target - a) / (b - a);
            return {path[i - 1].eps_a + t * (path[i].eps_a - path[i - 1].eps_a),
                    path[i - 1].eps_v +
                      t * (path[i].eps_v - path[i - 1].eps_v)};
          }
      }
    return {std::nan(""), std::nan("")};
  }

  /**
   * The model's path against the script's rows {p/p0, eps_a, eps_v}:
   * the largest relative difference, each row printed if @p verbose.
   */
  double
  compare(const std::vector<PathPoint>             &path,
          const std::vector<std::array<double, 3>> &reference,
          const bool                                verbose)
  {
    double max_error = 0.;
    for (const auto &row : reference)
      {
        const auto [eps_a, eps_v] = at_pressure(path, row[0]);
        const double error_a      = std::abs(eps_a / row[1] - 1.);
        const double error_v      = std::abs(eps_v / row[2] - 1.);
        // A NaN (a pressure the path does not reach) is the largest.
        max_error = (std::isfinite(error_a) && std::isfinite(error_v)) ?
                      std::max({max_error, error_a, error_v}) :
                      std::numeric_limits<double>::infinity();
        if (!verbose)
          continue;
        print("  p/p0 = %.6f: eps_a = %.6f", row[0], eps_a);
        print("    (script %.6f), eps_v = %.6f", row[1], eps_v);
        print("    (script %.6f), relative differences x 1e3: %.2f",
              row[2],
              1e3 * error_a);
        print("    and %.2f", 1e3 * error_v);
      }
    return max_error;
  }

  /**
   * Drained compression from p0 to the axial log strain @p final_strain in
   * steps of @p step; the path from the step of the largest p on (the
   * branch where p is monotone: all of it if p grows to the end).
   */
  std::vector<PathPoint>
  drained_path(Sample      &sample,
               const double final_strain,
               const double step,
               double      &peak_q)
  {
    std::vector<PathPoint> path = {{sample.p(), 0., 0.}};
    peak_q                      = 0.;
    const unsigned int n_steps  = std::lround(final_strain / step);
    for (unsigned int i = 1; i <= n_steps; ++i)
      {
        drained_step(sample, std::exp(-step * i));
        path.push_back({sample.p(), step * i, -sample.log_volume()});
        peak_q = std::max(peak_q, sample.q());
      }
    unsigned int top = 0;
    for (unsigned int i = 0; i < path.size(); ++i)
      if (path[i].p > path[top].p)
        top = i;
    if (top + 1 == path.size())
      return path;
    return std::vector<PathPoint>(path.begin() + top, path.end());
  }

  /**
   * Cases (c) and (d): the drained test of a sample of @p ocr against the
   * script's rows @p reference, in steps of 1e-4 (printed) and 2e-4 (the
   * largest difference only: backward Euler's error is of first order).
   */
  void
  drained_compression(const double                              ocr,
                      const double                              final_strain,
                      const std::vector<std::array<double, 3>> &reference)
  {
    const ModifiedCamClay model(parameters(ocr));
    const double          M = 1.2, p_cs = 3. * p0 / (3. - M);
    Sample                coarse(model, p0), sample(model, p0);
    print("  p_c0/p0 = %.6f", sample.pc / p0);
    double     peak_q, coarse_peak_q;
    const auto path = drained_path(sample, final_strain, 1e-4, peak_q);
    const auto coarse_path =
      drained_path(coarse, final_strain, 2e-4, coarse_peak_q);
    if (ocr > 1.)
      print("  peak q/p0 = %.6f (the yield point's q_y/p0 = 5.3850530436) "
            "at axial strain %.4f",
            peak_q / p0,
            path[0].eps_a);
    const double error        = compare(path, reference, true);
    const double coarse_error = compare(coarse_path, reference, false);
    impm_tests::check_below(
      "  strains against the script, largest relative difference", error, 5e-3);
    print("  largest relative difference x 1e3 in steps of 1e-4: %.2f, "
          "2e-4: %.2f",
          1e3 * error,
          1e3 * coarse_error);
    print("  at the end (axial strain %.2f): q/(M p) = %.6f",
          final_strain,
          sample.q() / (M * sample.p()));
    print("    p/p_cs = %.6f, p_c/(2p) = %.6f",
          sample.p() / p_cs,
          sample.pc / (2. * sample.p()));
    print("    p_c/p0 = %.6f, eps_v = %.6f",
          sample.pc / p0,
          -sample.log_volume());
  }

  /**
   * The returned state against the return's equations, recomputed here:
   * the elastic law between the returned stress and elastic strain, the
   * hardening law, the flow rule (its volumetric and deviatoric parts) in
   * strain, and f = 0 (f <= 0 if elastic). Strain residuals are absolute:
   * at p = p0 exp(-15) = 0.03 Pa the stress's round-off, 2G times that of
   * strains of 0.1 (1e-10 Pa), is 1e-9 of p.
   */
  void
  check_return(const ModifiedCamClay       &model,
               const std::array<double, 3> &trial_strain,
               const double                 pcn)
  {
    const auto   r = model.principal_return(trial_strain, pcn);
    const double G = 3e6, M2 = 1.44;
    const double kappa = model.modified_kappa();
    const double theta = model.modified_lambda() - kappa;
    // Invariants (compression positive) of a principal triple.
    const auto invariants = [](const std::array<double, 3> &x) {
      const double mean = (x[0] + x[1] + x[2]) / 3.;
      double       norm = 0.;
      for (unsigned int a = 0; a < 3; ++a)
        norm += (x[a] - mean) * (x[a] - mean);
      return std::array<double, 2>{{-3. * mean, std::sqrt(norm)}};
    };
    const auto   stress = invariants(r.stress);
    const double p = stress[0] / 3., q = std::sqrt(1.5) * stress[1];
    const auto   elastic = invariants(r.elastic_strain);
    const auto   trial   = invariants(trial_strain);
    const double ev_e = elastic[0], es_e = std::sqrt(2. / 3.) * elastic[1];
    const double ev_tr = trial[0], es_tr = std::sqrt(2. / 3.) * trial[1];
    const double pc     = r.preconsolidation_pressure,
                 dgamma = r.plastic_multiplier;
    const double p_e = p0 * std::exp(ev_e / kappa), q_e = 3. * G * es_e;
    std::cout << "    " << (r.plastic ? "plastic" : "elastic");
    print(", p/p_c = %.8f", p / pc);
    print("    p/p0 = %.8e, q/p0 = %.8e", p / p0, q / p0);
    const double residuals[] = {kappa * std::log(p / p0) - ev_e,
                                q / (3. * G) - es_e,
                                theta * std::log(pc / pcn) - (ev_tr - ev_e),
                                dgamma * (2. * p_e - pc) - (ev_tr - ev_e),
                                dgamma * 2. * q_e / M2 - (es_tr - es_e)};
    double       worst       = 0.;
    for (const double residual : residuals)
      worst = std::max(worst, std::abs(residual));
    impm_tests::check_below("    the return's equations, largest strain "
                            "residual",
                            worst,
                            1e-10);
    const double f =
      (q_e * q_e / M2 + p_e * (p_e - pc)) / (q_e * q_e / M2 + p_e * (p_e + pc));
    // Elastic: f below the model's yield margin, 1e-10 of the same scale.
    impm_tests::check_below(r.plastic ? "    |f|/(q^2/M^2 + p (p + p_c))" :
                                        "    f/(q^2/M^2 + p (p + p_c))",
                            r.plastic ? std::abs(f) : f,
                            1e-10);
  }

  void
  hard_cases()
  {
    const ModifiedCamClay model(parameters(1.));
    std::cout << "(e) hard cases" << std::endl;
    // The tip: p = p_c = p0, q = 0 (b^e = I, NC).
    std::cout << "  tip, isotropic compression by ln J = -0.01:" << std::endl;
    check_return(model, {{-0.01 / 3, -0.01 / 3, -0.01 / 3}}, p0);
    std::cout << "  tip, isotropic unloading by ln J = 0.001:" << std::endl;
    check_return(model, {{0.001 / 3, 0.001 / 3, 0.001 / 3}}, p0);
    std::cout << "  tip, isochoric shear 1e-3:" << std::endl;
    check_return(model, {{1e-3, -1e-3, 0.}}, p0);
    std::cout << "  tip, isochoric shear 1e-9:" << std::endl;
    check_return(model, {{1e-9, -1e-9, 0.}}, p0);
    // Very low mean stress: swelling by ln J = 0.3 from p0 (elastic), p =
    // p0 exp(-15), then shear on the dry side.
    std::cout << "  swollen by ln J = 0.3:" << std::endl;
    check_return(model, {{0.1, 0.1, 0.1}}, p0);
    std::cout << "  swollen by ln J = 0.3, shear 1e-5:" << std::endl;
    check_return(model, {{0.1 + 1e-5, 0.1 - 1e-5, 0.1}}, p0);
    std::cout << "  swollen by ln J = 0.3, shear 0.05:" << std::endl;
    check_return(model, {{0.15, 0.05, 0.1}}, p0);
    // A trial state a Hencky law would put in tension: uniaxial extension.
    std::cout << "  uniaxial extension 0.2:" << std::endl;
    check_return(model, {{0.2, 0., 0.}}, p0);
    // The far expansion: the exponential underflows and the update throws.
    std::cout << "  swollen by ln J = 30:";
    try
      {
        model.principal_return({{10., 10., 10.}}, p0);
        std::cout << " no exception" << std::endl;
      }
    catch (const ExceptionBase &)
      {
        std::cout << " an exception (fails the Newton iteration)" << std::endl;
      }
  }
} // namespace

int
main()
{
  isotropic_compression();
  undrained_compression();
  std::cout << "(c) drained triaxial compression, normally consolidated"
            << std::endl;
  // python3 scripts/cam_clay_drained.py, case (c): p/p0, eps_a, eps_v.
  drained_compression(1.,
                      0.46,
                      {{{1.133333, 0.0157202458, 0.0191536181},
                        {1.266667, 0.0468430448, 0.0432004846},
                        {1.400000, 0.0963414064, 0.0666268073},
                        {1.533333, 0.1805864051, 0.0877940260},
                        {1.600000, 0.2617840913, 0.0974555490},
                        {1.633333, 0.3409802015, 0.1020654779},
                        {1.653333, 0.4441203893, 0.1047634015}}});
  print("  the critical state's eps_v, lambda* ln(p_cs/p0) + (lambda* - "
        "kappa*) ln 2 = %.6f",
        0.1 * std::log(3. / 1.8) + 0.08 * std::log(2.));
  std::cout << "(d) drained triaxial compression, OCR = 10" << std::endl;
  // python3 scripts/cam_clay_drained.py, case (d), the softening branch.
  drained_compression(10.,
                      0.34,
                      {{{2.569347, 0.0768184114, 0.0064369896},
                        {2.343677, 0.0936184404, -0.0097093565},
                        {2.118007, 0.1230301715, -0.0284799047},
                        {1.892337, 0.1840978227, -0.0507300164},
                        {1.779502, 0.2531671873, -0.0635233854},
                        {1.723084, 0.3262678179, -0.0704159092}}});
  hard_cases();
}
