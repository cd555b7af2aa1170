#include <impm/base/names.h>
#include <impm/core/parameters.h>
#include <impm/core/rigid_body.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace impm
{
  template <int dim>
  void
  RigidBody<dim>::declare_parameters(ParameterHandler &prm)
  {
    for (unsigned int k = 1; k <= max_rigid_bodies; ++k)
      {
        prm.enter_subsection("Rigid body " + std::to_string(k));
        RigidShape<dim>::declare_parameters(prm);
        prm.declare_entry("Displacement",
                          "",
                          Patterns::List(Patterns::Double(), 0, 3),
                          "The body's displacement at the full load, one "
                          "component per dimension, in m (empty: zero); "
                          "ramped with the load factor like every load. "
                          "Zero on the 'Force-driven components'.");
        prm.declare_entry("Rotation",
                          "0",
                          Patterns::Double(-360., 360.),
                          "The angle the body turns by at the full load, "
                          "in degrees, ramped with the load factor like "
                          "'Displacement' (-360 to 360; 0: it does not "
                          "turn): counter-clockwise about z in 2D, "
                          "right-handed about 'Rotation axis' in 3D, about "
                          "'Rotation centre' moving with the displacement. "
                          "A turning box is probed like a polygon (2D) or "
                          "a triangulated surface (3D), at 'Face quadrature "
                          "points'.");
        prm.declare_entry("Rotation axis",
                          "0, 0, 1",
                          Patterns::List(Patterns::Double(), 3, 3),
                          "3D: the direction of the rotation's axis (any "
                          "length > 0).");
        prm.declare_entry("Rotation centre",
                          "",
                          Patterns::List(Patterns::Double(), 0, 3),
                          "The point the body turns about, before its "
                          "displacement, one coordinate per dimension "
                          "(empty: the centre of the body's bounding "
                          "box).");
        prm.declare_entry(
          "Force-driven components",
          "",
          Patterns::Anything(),
          "The components (a comma-separated list of x, y, z; empty: none) "
          "in which the body is pushed by 'Force' instead of moved by "
          "'Displacement': its displacement there is an unknown of the "
          "Newton solve, found by the balance of the force with the "
          "material's contact force. The body must touch the material "
          "(a face of a point's domain on or inside its surface) from the "
          "first load step.");
        prm.declare_entry("Force",
                          "",
                          Patterns::List(Patterns::Double(), 0, 3),
                          "The force on the body at the full load, one "
                          "component per dimension, in N (per m of "
                          "thickness in 2D); ramped with the load factor. "
                          "Zero but on the 'Force-driven components' "
                          "(empty: zero).");
        prm.declare_entry(
          "Friction",
          "frictionless",
          Patterns::Selection("frictionless|coulomb|rough"),
          "How the surface resists sliding: frictionless, coulomb (stick "
          "below 'Friction coefficient' times the pressure, slip at it) or "
          "rough (no slip).");
        prm.declare_entry("Friction coefficient",
                          "0",
                          Patterns::Double(0.),
                          "Coulomb friction coefficient mu >= 0 (Friction = "
                          "coulomb).");
        prm.declare_entry(
          "Penalty factor",
          "100",
          Patterns::Double(0.),
          "alpha > 0: the contact's normal and tangential stiffness per "
          "area is alpha E / h (E: Young's modulus of the touching "
          "point's material, h: the smallest cell size), so a pressure p "
          "lets the material into the body by p h / (alpha E). The default "
          "100 keeps the error of the plate benchmark under 1 % "
          "(doc/benchmarks). With an explicit integrator the stable time "
          "step is that of a material with the P-wave modulus M + alpha "
          "E / 2: 0.16 of the material's own at 100 and nu = 0.3, 0.46 at "
          "10.");
        prm.declare_entry(
          "Face quadrature points",
          "3",
          Patterns::Integer(1, 4),
          "A disc, sphere, cone or polygon touches each face of a point's "
          "domain at this many Gauss points per direction along the face "
          "(1 to 4; 1: the face's centre alone, which a sharp tip or a "
          "small disc can pass between). The default 3 took the pipe "
          "scene through without a cut and fastest (doc/benchmarks). A box "
          "uses the face's centre and the exact part of the face over its "
          "side instead.");
        prm.declare_entry(
          "Tangential penalty factor",
          "10",
          Patterns::Double(0.),
          "alpha_t > 0: the stiffness per area of a sticking contact "
          "against sliding is alpha_t E / h, so a sticking face creeps by "
          "t h / (alpha_t E) under a friction traction t. Lower than the "
          "normal factor: with alpha_t = 100 Newton cycles between stick "
          "and slip on a block resting on a Coulomb floor "
          "(doc/benchmarks).");
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  RigidBody<dim>::parse_parameters(ParameterHandler  &prm,
                                   const unsigned int number)
  {
    name = "Rigid body " + std::to_string(number);
    prm.enter_subsection(name);
    shape = RigidShape<dim>::create(prm, name);
    // Empty: the body stays where it is.
    const auto values =
      Parameters::get_optional_vector(prm, name, "Displacement", dim);
    for (unsigned int d = 0; d < dim; ++d)
      displacement[d] = values.empty() ? 0. : values[d];
    parse_force(prm);
    parse_rotation(prm);
    friction             = static_cast<Friction>(Parameters::selection_index(
      friction_names, name + "/Friction", prm.get("Friction")));
    friction_coefficient = prm.get_double("Friction coefficient");
    if (friction == Friction::coulomb && !(friction_coefficient > 0.))
      Parameters::bad_value(name + "/Friction coefficient",
                            prm.get("Friction coefficient"),
                            "Coulomb friction needs a coefficient > 0 (or "
                            "Friction = frictionless).");
    penalty_factor = prm.get_double("Penalty factor");
    if (!(penalty_factor > 0.))
      Parameters::bad_value(name + "/Penalty factor",
                            prm.get("Penalty factor"),
                            "it must be > 0.");
    face_quadrature_points    = prm.get_integer("Face quadrature points");
    tangential_penalty_factor = prm.get_double("Tangential penalty factor");
    if (friction != Friction::frictionless && !(tangential_penalty_factor > 0.))
      Parameters::bad_value(name + "/Tangential penalty factor",
                            prm.get("Tangential penalty factor"),
                            "it must be > 0 with friction.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  RigidBody<dim>::parse_force(ParameterHandler &prm)
  {
    force_components.clear();
    const std::string entry = name + "/Force-driven components";
    const std::string value = prm.get("Force-driven components");
    for (const std::string &item : Utilities::split_string_list(value, ','))
      {
        unsigned int axis = dim;
        for (unsigned int d = 0; d < dim; ++d)
          if (item == Names::axis(d))
            axis = d;
        if (axis == dim)
          Parameters::bad_value(entry,
                                value,
                                std::string("it must be a list of ") +
                                  (dim == 2 ? "x, y" : "x, y, z") +
                                  ", each at most once (empty: none).");
        if (is_force_driven(axis))
          Parameters::bad_value(entry, value, "each component at most once.");
        force_components.push_back(axis);
      }
    std::sort(force_components.begin(), force_components.end());
    // Empty: no force.
    const auto values =
      Parameters::get_optional_vector(prm, name, "Force", dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        force[d] = values.empty() ? 0. : values[d];
        if (force[d] != 0. && !is_force_driven(d))
          Parameters::bad_value(name + "/Force",
                                prm.get("Force"),
                                "a force acts only on the 'Force-driven "
                                "components' (component " +
                                  Names::axis(d) + " is not one).");
        if (displacement[d] != 0. && is_force_driven(d))
          Parameters::bad_value(name + "/Displacement",
                                prm.get("Displacement"),
                                "zero on the 'Force-driven components' "
                                "(component " +
                                  Names::axis(d) +
                                  " is one: 'Force' drives it).");
      }
  }



  template <int dim>
  void
  RigidBody<dim>::parse_rotation(ParameterHandler &prm)
  {
    rotation_angle = prm.get_double("Rotation") * numbers::PI / 180.;
    const auto box = bounding_box(Tensor<1, dim>());
    for (unsigned int d = 0; d < dim; ++d)
      rotation_centre[d] = 0.5 * (box.first[d] + box.second[d]);
    const auto centre =
      Parameters::get_optional_vector(prm, name, "Rotation centre", dim);
    for (unsigned int d = 0; d < centre.size(); ++d)
      rotation_centre[d] = centre[d];
    if (!rotates())
      return;
    if constexpr (dim == 3)
      {
        const auto axis =
          Parameters::get_vector(prm, name, "Rotation axis", dim);
        for (unsigned int d = 0; d < dim; ++d)
          rotation_axis[d] = axis[d];
        if (!(rotation_axis.norm() > 0.))
          Parameters::bad_value(name + "/Rotation axis",
                                prm.get("Rotation axis"),
                                "the direction needs a length > 0.");
        rotation_axis /= rotation_axis.norm();
      }
    if (auto turning = shape->turning_form())
      shape = std::move(turning);
  }



  template <int dim>
  std::string
  RigidBody<dim>::description() const
  {
    std::ostringstream out;
    out << name << ": " << shape->description();
    out << ", moved by [" << displacement << "]";
    if (rotates())
      {
        out << ", turned by " << rotation_angle * 180. / numbers::PI
            << " degrees about (" << rotation_centre << ")";
        if (dim == 3)
          out << " axis (" << rotation_axis << ")";
      }
    if (!force_components.empty())
      {
        out << " but pushed by [" << force << "] in";
        for (const unsigned int d : force_components)
          out << ' ' << Names::axis(d);
      }
    out << ", " << friction_names[static_cast<unsigned int>(friction)];
    if (friction == Friction::coulomb)
      out << " mu = " << friction_coefficient;
    if (face_points() > 1)
      out << ", " << face_points() << " Gauss points per face direction";
    out << ", penalty factor " << penalty_factor;
    if (friction != Friction::frictionless)
      out << " (tangential " << tangential_penalty_factor << ")";
    return out.str();
  }



  template class RigidBody<2>;
  template class RigidBody<3>;
} // namespace impm
