#include <impm/base/errors.h>
#include <impm/coupling/time_integrator.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace impm
{
  void
  TimeIntegrator::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Integrator",
                      "Newmark",
                      Patterns::Selection("Newmark|generalised-alpha|"
                                          "explicit MUSL|explicit USL"),
                      "The time integrator: 'Newmark' (with 'Newmark "
                      "beta' and 'Newmark gamma'; the trapezoidal rule "
                      "by default) or 'generalised-alpha' (Chung and "
                      "Hulbert, with 'Spectral radius'), both implicit "
                      "in full Newton; or the explicit central "
                      "difference rule with lumped mass, 'explicit "
                      "MUSL' (the increment from the updated points' "
                      "momentum) or 'explicit USL' (from the nodes' "
                      "velocity), with its time step below 'Courant "
                      "number' times the stable one. USL is unstable "
                      "where a point enters a cell its neighbours do not "
                      "fill: the node's small mass makes its velocity "
                      "jump (doc/benchmarks/inertia.md); MUSL is not.");
    prm.declare_entry("Courant number",
                      "0.5",
                      Patterns::Double(0., 1.),
                      "Explicit integrators: the largest time step as a "
                      "fraction of the smallest cell size over the "
                      "largest speed of sound (above 0, at most 1), that "
                      "of the P-wave modulus M, or with rigid bodies of M "
                      "+ alpha E / 2 (their 'Penalty factor' alpha).");
    prm.declare_entry("FLIP fraction",
                      "1",
                      Patterns::Double(0., 1.),
                      "The points' new velocity: this fraction from "
                      "their velocity plus the nodes' change (FLIP), "
                      "the rest the nodes' new velocity (PIC, which "
                      "damps). 1: FLIP. Per step, or per 'FLIP "
                      "reference step' where that is set.");
    prm.declare_entry("FLIP reference step",
                      "0",
                      Patterns::Double(0.),
                      "The time step in s that 'FLIP fraction' phi is "
                      "given for: a step of length dt then blends with "
                      "phi^(dt / this step), so that the PIC share damps "
                      "the same per second at any time step (under "
                      "refinement, in a cut step, and explicit against "
                      "implicit steps). 0: phi in every step, whatever "
                      "its length, so that the damping per second grows "
                      "as the step shrinks (the granular column at a = 1 "
                      "with phi 0.95 ran out 1.15 L0 in implicit steps of "
                      "0.005 s and 0.76 L0 in explicit steps of 0.00029 "
                      "s; with this at 0.005 s, 1.37 L0 explicit).");
    prm.declare_entry("Velocity update",
                      "FLIP/PIC",
                      Patterns::Selection("FLIP/PIC|APIC"),
                      "How the points take the nodes' new velocity: "
                      "'FLIP/PIC' (the blend of 'FLIP fraction'), or "
                      "'APIC', the affine particle-in-cell transfer "
                      "(Jiang et al. 2015, with the gradient of the "
                      "weights): each point takes the nodes' new "
                      "velocity v_p = sum_I N_Ip v_I and its gradient "
                      "C_p = sum_I v_I grad N_Ip (a declared point field, "
                      "'velocity_gradient'), and gives the nodes the "
                      "momentum of that affine field, m_p N_Ip (v_p + C_p "
                      "(x_I - x_p)). A rigid rotation stays rigid (FLIP "
                      "turns it into velocity noise and strain energy, "
                      "PIC slows it down). It damps far less than PIC "
                      "but more than FLIP where the velocity varies "
                      "within a cell: two colliding elastic discs lose 44 "
                      "% of their energy (FLIP 0.2 %, PIC 97 %). With "
                      "implicit steps and rigid contact use "
                      "generalised-alpha with 'Spectral radius' at most "
                      "0.5: APIC keeps the contact's fast oscillation, "
                      "which the trapezoidal rule leaves undamped. Lumped "
                      "mass only; 'FLIP fraction' must stay 1.");
    prm.declare_entry("Newmark beta",
                      "0.25",
                      Patterns::Double(0., 0.5),
                      "beta of the Newmark rule (0.25 with gamma = 0.5: "
                      "the trapezoidal rule, unconditionally stable and "
                      "without numerical damping); from above 0 to "
                      "0.5.");
    prm.declare_entry("Newmark gamma",
                      "0.5",
                      Patterns::Double(0., 1.),
                      "gamma of the Newmark rule (0.5: no numerical "
                      "damping; above 0.5 damps); from 0.5 to 1, and "
                      "at most 4 beta for unconditional stability.");
    prm.declare_entry("Spectral radius",
                      "0.8",
                      Patterns::Double(0., 1.),
                      "generalised-alpha's spectral radius at infinite "
                      "frequency, from 0 (the most damping of the "
                      "highest frequencies) to 1 (none: the "
                      "trapezoidal rule's energy conservation).");
    prm.declare_entry("Local damping",
                      "0",
                      Patterns::Double(0., 1.),
                      "Explicit integrators: local non-viscous damping "
                      "(Cundall's, for dynamic relaxation to a static "
                      "state): each node's force reduced by this fraction "
                      "of its size against the node's velocity, -alpha "
                      "|f| sign(v); from 0 (none) to below 1. It damps "
                      "every frequency alike and leaves the static state "
                      "unchanged.");
    prm.declare_entry("Mass",
                      "lumped",
                      Patterns::Selection("lumped|consistent"),
                      "Implicit integrators: 'lumped' (each node's mass "
                      "the sum of its points' shares; the points' "
                      "velocities mapped to the nodes and back, FLIP/PIC) "
                      "or 'consistent' (the mass matrix sum_p m_p N_Ip "
                      "N_Jp plus 'Mass regularisation' times the lumped "
                      "one, in the matrix and the inertial force, and the "
                      "nodes' velocity and acceleration of each step's "
                      "start solved from the points' momentum with it: "
                      "two conjugate-gradient solves a step; the energy "
                      "of the trapezoidal rule is then kept). The "
                      "explicit integrators are lumped.");
    prm.declare_entry("Mass regularisation",
                      "1e-6",
                      Patterns::Double(0., 1.),
                      "With 'Mass = consistent': the fraction of the "
                      "lumped mass added to the consistent one, which "
                      "keeps the mass matrix definite where few points "
                      "share a node (a barely filled cell; from 0 to 1). "
                      "The lumped part loses energy as the lumped mass "
                      "does: the vibrating bar loses 5e-6 of its energy a "
                      "period at 1e-6, 3e-4 at 1e-3 (lumped: 2.2e-4).");
    prm.declare_entry("Mass damping",
                      "0",
                      Patterns::Double(0.),
                      "The mass-proportional Rayleigh damping "
                      "coefficient alpha in 1/s (damping force alpha M "
                      "v; a mode of angular frequency omega is damped "
                      "at the ratio alpha / (2 omega)). 0: none.");
    prm.declare_entry("Stiffness damping",
                      "0",
                      Patterns::Double(0.),
                      "The stiffness-proportional Rayleigh damping "
                      "coefficient beta in s: a viscous stress beta D : "
                      "d at every point, with its material's elastic "
                      "moduli (a pressure-dependent law's reference ones) "
                      "and the rate of strain d of the nodal velocity, so "
                      "that a mode of angular frequency omega is damped at "
                      "the ratio beta omega / 2 (the highest frequencies "
                      "most). With 'Mass damping' alpha: Rayleigh damping "
                      "C = alpha M + beta K. It lowers the stable explicit "
                      "time step by the factor sqrt(1 + z^2) - z, z = beta "
                      "/ (the undamped stable step). 0: none.");
  }



  TimeIntegrator::TimeIntegrator(const ParameterHandler &prm)
  {
    const std::string name = prm.get("Integrator");
    explicit_order         = name == "explicit MUSL" ? ExplicitOrder::musl :
                             name == "explicit USL"  ? ExplicitOrder::usl :
                                                       ExplicitOrder::none;
    courant_number         = prm.get_double("Courant number");
    flip_fraction          = prm.get_double("FLIP fraction");
    flip_reference_step    = prm.get_double("FLIP reference step");
    affine_transfer        = prm.get("Velocity update") == "APIC";
    generalised_alpha      = name == "generalised-alpha";
    spectral_radius        = prm.get_double("Spectral radius");
    mass_damping           = prm.get_double("Mass damping");
    stiffness_damping      = prm.get_double("Stiffness damping");
    local_damping          = prm.get_double("Local damping");
    consistent_mass        = prm.get("Mass") == "consistent";
    mass_regularisation    = prm.get_double("Mass regularisation");
    if (generalised_alpha)
      {
        alpha_m = (2. * spectral_radius - 1.) / (spectral_radius + 1.);
        alpha_f = spectral_radius / (spectral_radius + 1.);
        gamma   = 0.5 - alpha_m + alpha_f;
        beta    = 0.25 * (1. - alpha_m + alpha_f) * (1. - alpha_m + alpha_f);
      }
    else
      {
        alpha_m = alpha_f = 0.;
        beta              = prm.get_double("Newmark beta");
        gamma             = prm.get_double("Newmark gamma");
      }
    if (!(courant_number > 0.))
      throw InputError(
        "Parameter 'Inertia/Courant number' = " + prm.get("Courant number") +
        " is not allowed: it must be above 0.");
    if (local_damping >= 1.)
      throw InputError(
        "Parameter 'Inertia/Local damping' = " + prm.get("Local damping") +
        " is not allowed: it must be below 1 (1 would stop "
        "every node).");
    if (!is_explicit() && local_damping > 0.)
      throw InputError("Inertia: 'Local damping' needs an explicit "
                       "integrator: its force, -alpha |f| sign(v), has no "
                       "derivative for Newton's method; use 'Mass damping' "
                       "with Newmark or generalised-alpha.");
    if (is_explicit() && consistent_mass)
      throw InputError("Inertia: 'Mass' = 'consistent' needs an implicit "
                       "integrator (Newmark or generalised-alpha); the "
                       "explicit ones are lumped.");
    if (affine_transfer && flip_fraction < 1.)
      throw InputError(
        "Inertia: 'FLIP fraction' = " + prm.get("FLIP fraction") +
        " blends FLIP with PIC; with 'Velocity update' = "
        "'APIC' the points take the nodes' new velocity and "
        "its gradient (no FLIP part): leave 'FLIP fraction' "
        "at 1.");
    if (affine_transfer && consistent_mass)
      throw InputError("Inertia: 'Velocity update' = 'APIC' needs 'Mass' = "
                       "'lumped': the consistent mass's projection already "
                       "gives the nodes an affine field of the points' "
                       "velocities.");
    if (is_explicit())
      return;
    if (!(beta > 0.))
      throw InputError("Parameter 'Inertia/Newmark beta' = '" +
                       prm.get("Newmark beta") +
                       "' is not allowed: it must be > 0 (an implicit "
                       "rule).");
    if (gamma < 0.5 || 4. * beta < gamma)
      throw InputError("Inertia: Newmark gamma = " + prm.get("Newmark gamma") +
                       " with beta = " + prm.get("Newmark beta") +
                       " is not unconditionally stable: it needs 0.5 <= "
                       "gamma <= 4 beta.");
  }



  void
  TimeIntegrator::check_velocity_update(const BasisType basis,
                                        const bool      rigid_bodies,
                                        const bool      print) const
  {
    if (affine_transfer && is_explicit() && basis == BasisType::standard_mpm)
      throw InputError(
        "Inertia: 'Velocity update' = 'APIC' with an explicit integrator "
        "needs 'Material points/Basis' = 'GIMP': with standard MPM's "
        "weights a node that a point barely reaches has a tiny mass and a "
        "large change of velocity, which the point's velocity gradient "
        "weighs fully (a spinning disc breaks up in a few hundred steps); "
        "use GIMP, or an implicit integrator.");
    // APIC keeps a node's velocity however few points share it: the fast
    // oscillation of a rigid contact's penalty, which an implicit step does
    // not resolve, survives the trapezoidal rule undamped.
    if (affine_transfer && !is_explicit() && rigid_bodies &&
        !(generalised_alpha && spectral_radius <= 0.5) && print)
      std::cerr << "Warning: Inertia: 'Velocity update' = 'APIC' with rigid "
                   "bodies keeps the contact's fast oscillation, which an "
                   "implicit step does not resolve and the trapezoidal rule "
                   "does not damp: use 'generalised-alpha' with 'Spectral "
                   "radius' at most 0.5 (a block sliding on a rough rigid "
                   "floor lifted 9 mm with the trapezoidal rule, 0.1 mm "
                   "with 0.5)."
                << std::endl;
  }



  double
  TimeIntegrator::flip_fraction_of_step(const double time_step) const
  {
    if (flip_reference_step > 0. && flip_fraction < 1.)
      return std::pow(flip_fraction, time_step / flip_reference_step);
    return flip_fraction;
  }



  std::string
  TimeIntegrator::description() const
  {
    std::ostringstream out;
    if (is_explicit())
      out << "explicit central differences ("
          << (explicit_order == ExplicitOrder::musl ?
                "MUSL" :
                "USL, unstable where points enter cells their neighbours "
                "do not fill; MUSL is not")
          << ", Courant number " << courant_number << ")";
    else if (generalised_alpha)
      out << "generalised-alpha (spectral radius " << spectral_radius
          << ": alpha_m " << alpha_m << ", alpha_f " << alpha_f << ")";
    else
      out << "Newmark (beta " << beta << ", gamma " << gamma
          << (beta == 0.25 && gamma == 0.5 ? ", the trapezoidal rule" : "")
          << ")";
    out << (consistent_mass ? ", consistent mass" : ", lumped mass");
    if (mass_damping > 0.)
      out << ", mass damping " << mass_damping << " 1/s";
    if (stiffness_damping > 0.)
      out << ", stiffness damping " << stiffness_damping << " s";
    if (local_damping > 0.)
      out << ", local damping " << local_damping;
    if (affine_transfer)
      out << ", APIC velocity update";
    else if (flip_fraction < 1.)
      {
        out << ", FLIP fraction " << flip_fraction;
        if (flip_reference_step > 0.)
          out << " per " << flip_reference_step << " s";
      }
    return out.str();
  }
} // namespace impm
