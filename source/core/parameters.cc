#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/core/effects.h>
#include <impm/core/parameters.h>
#include <impm/mechanics/material.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace impm
{
  namespace Parameters
  {
    void
    bad_value(const std::string &entry,
              const std::string &value,
              const std::string &allowed)
    {
      throw InputError("Parameter '" + entry + "' = '" + value +
                       "' is not allowed: " + allowed);
    }



    namespace
    {
      /**
       * The numbers of the comma-separated @p words of entry @p entry (=
       * @p value); a word that is not a finite number is an error naming
       * the entry.
       */
      std::vector<double>
      to_numbers(const std::vector<std::string> &words,
                 const std::string              &entry,
                 const std::string              &value)
      {
        std::vector<double> numbers;
        for (const auto &word : words)
          {
            char        *end    = nullptr;
            const double number = std::strtod(word.c_str(), &end);
            if (word.empty() || *end != '\0' || !std::isfinite(number))
              bad_value(entry, value, "'" + word + "' is not a finite number.");
            numbers.push_back(number);
          }
        return numbers;
      }



      /**
       * The @p n comma-separated numbers of @p entry, or none if
       * @p may_be_empty; anything else is an error naming the entry.
       */
      std::vector<double>
      get_numbers(const ParameterHandler &prm,
                  const std::string      &section,
                  const std::string      &entry,
                  const unsigned int      n,
                  const bool              may_be_empty)
      {
        const std::string         value = prm.get(entry);
        const std::vector<double> numbers =
          to_numbers(Utilities::split_string_list(value),
                     section + "/" + entry,
                     value);
        if (numbers.size() != n && !(may_be_empty && numbers.empty()))
          bad_value(section + "/" + entry,
                    value,
                    "it needs " + std::to_string(n) +
                      " comma-separated numbers" +
                      (may_be_empty ? ", or none." : " (one per dimension)."));
        return numbers;
      }
    } // namespace



    std::vector<double>
    get_optional_vector(const ParameterHandler &prm,
                        const std::string      &section,
                        const std::string      &entry,
                        const unsigned int      n)
    {
      return get_numbers(prm, section, entry, n, true);
    }



    std::vector<double>
    get_vector(const ParameterHandler &prm,
               const std::string      &section,
               const std::string      &entry,
               const unsigned int      n)
    {
      return get_numbers(prm, section, entry, n, false);
    }



    std::vector<std::vector<double>>
    get_point_list(const ParameterHandler &prm,
                   const std::string      &section,
                   const std::string      &entry,
                   const unsigned int      n)
    {
      const std::string                value = prm.get(entry);
      std::vector<std::vector<double>> points;
      for (const auto &point : Utilities::split_string_list(value, ';'))
        {
          points.push_back(to_numbers(Utilities::split_string_list(point),
                                      section + "/" + entry,
                                      value));
          if (points.back().size() != n)
            bad_value(section + "/" + entry,
                      value,
                      "each position 'x, y; x, y; ...' needs " +
                        std::to_string(n) + " coordinates.");
        }
      return points;
    }



    void
    Scene::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Scene name",
                        "scene",
                        Patterns::Anything(),
                        "Name of the scene, written into summary.json.");
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Space dimension: 2 (plane strain) or 3.");
      prm.declare_entry("Output directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Directory for all output (created if missing), "
                        "relative to the working directory. It holds one "
                        "run: the files of an earlier run of the same scene "
                        "(same name and scene file) are removed at the "
                        "start, and a directory that holds another "
                        "scene's run is refused (see 'Existing output').");
      prm.declare_entry("Existing output",
                        "refuse",
                        Patterns::Selection("refuse|overwrite"),
                        "What to do when 'Output directory' holds the run "
                        "of another scene: refuse (stop with an error "
                        "naming it) or overwrite (remove its files first; "
                        "the command-line flag --overwrite sets this).");
    }

    void
    Scene::parse_parameters(const ParameterHandler &prm)
    {
      name                      = prm.get("Scene name");
      dimension                 = prm.get_integer("Dimension");
      output_directory          = prm.get("Output directory");
      overwrite_existing_output = prm.get("Existing output") == "overwrite";
      if (output_directory.empty())
        bad_value("Output directory", "", "it must not be empty.");
    }



    template <int dim>
    void
    Grid<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Grid");
      prm.declare_entry(
        "Axisymmetric",
        "false",
        Patterns::Bool(),
        "2D only: the grid is the meridian plane of a solid of revolution "
        "about the y axis, x being the radius r (>= 0) and y the axis z. "
        "Every volume, mass, area and force is that of the whole ring "
        "(2 pi r per unit of the plane's area or length), and the points "
        "carry the hoop strain and stress (stress_zz is the hoop stress). "
        "A grid that reaches the axis (Lower corner x = 0) needs the radial "
        "displacement held there: 'Condition x-' roller or fixed. F-bar "
        "shares the volume change with the hoop stretch. Both formulations "
        "(Solver/Formulation) work in it.");
      prm.declare_entry("Lower corner",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Lower corner of the background grid, one "
                        "coordinate per dimension, in m.");
      prm.declare_entry("Upper corner",
                        "3.125, 50",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Upper corner of the background grid, in m.");
      prm.declare_entry("Number of cells",
                        "1, 16",
                        Patterns::List(Patterns::Integer(1), 2, 3),
                        "Number of cells in each direction (>= 1).");
      for (const char *face : Names::faces)
        {
          prm.declare_entry(
            std::string("Condition ") + face,
            "none",
            Patterns::Selection(
              "none|roller|fixed|prescribed|prescribed normal|normal only"),
            std::string("Displacement condition on the grid face ") + face +
              ": none, roller (normal component zero), fixed (all "
              "components zero), prescribed (all components follow "
              "'Displacement " +
              face +
              "', ramped over the load steps), prescribed normal (the "
              "normal component follows it, the others are free) or normal "
              "only (the tangential components zero, the normal one free: "
              "the sides of a shear column). z faces are used in 3D only.");
          prm.declare_entry(std::string("Displacement ") + face,
                            "0, 0",
                            Patterns::List(Patterns::Double(), 2, 3),
                            std::string("Displacement of the face ") + face +
                              " at the full load, in m, when its condition "
                              "is prescribed.");
          prm.declare_entry(std::string("Region ") + face,
                            "",
                            Patterns::List(Patterns::Double(), 0, 6),
                            std::string("If given (lower corner, then upper "
                                        "corner), the condition on face ") +
                              face +
                              " holds only for its nodes inside this box; "
                              "empty: the whole face.");
        }
      prm.leave_subsection();
    }

    template <int dim>
    void
    Grid<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Grid");
      axisymmetric     = prm.get_bool("Axisymmetric");
      const auto lower = get_vector(prm, "Grid", "Lower corner", dim);
      const auto upper = get_vector(prm, "Grid", "Upper corner", dim);
      const auto cells = get_vector(prm, "Grid", "Number of cells", dim);
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower_corner[d] = lower[d];
          upper_corner[d] = upper[d];
          n_cells[d]      = static_cast<unsigned int>(cells[d]);
          if (!(upper[d] > lower[d]))
            bad_value("Grid/Upper corner",
                      prm.get("Upper corner"),
                      "each coordinate must exceed that of 'Lower corner' (" +
                        prm.get("Lower corner") + ").");
        }
      for (unsigned int f = 0; f < 2 * dim; ++f)
        {
          const std::string face = Names::face(f);
          face_conditions[f]     = static_cast<FaceCondition>(
            selection_index(face_condition_names,
                            "Grid/Condition " + face,
                            prm.get("Condition " + face)));
          face_displacements[f] = 0;
          // A face that is not prescribed takes no displacement: any
          // number that is not zero was meant for it (the default "0, 0"
          // stands in 3D too).
          const std::vector<double> u =
            is_prescribed(face_conditions[f]) ?
              get_vector(prm, "Grid", "Displacement " + face, dim) :
              Utilities::string_to_double(
                Utilities::split_string_list(prm.get("Displacement " + face)));
          for (unsigned int d = 0; d < u.size(); ++d)
            if (is_prescribed(face_conditions[f]))
              face_displacements[f][d] = u[d];
            else if (u[d] != 0.)
              throw InputError("'Grid/Displacement " + face +
                               "' is not zero, but 'Condition " + face +
                               "' does not prescribe the face's motion; set "
                               "'Condition " +
                               face +
                               "' to prescribed (or prescribed normal), or "
                               "the displacement to zero.");
          const auto region =
            get_optional_vector(prm, "Grid", "Region " + face, 2 * dim);
          face_has_region[f] = !region.empty();
          if (face_has_region[f] && face_conditions[f] == FaceCondition::none)
            throw InputError("'Grid/Region " + face + "' limits 'Condition " +
                             face +
                             "' to a part of the face, but the condition is "
                             "none (the face is free): give the condition, "
                             "or leave the region empty.");
          for (unsigned int d = 0; d < dim && face_has_region[f]; ++d)
            {
              face_regions[f].first[d]  = region[d];
              face_regions[f].second[d] = region[dim + d];
            }
        }
      if (axisymmetric)
        check_axisymmetric_grid(prm);
      prm.leave_subsection();
    }



    template <int dim>
    void
    Grid<dim>::check_axisymmetric_grid(const ParameterHandler &prm) const
    {
      if (dim != 2)
        bad_value("Grid/Axisymmetric",
                  "true",
                  "axisymmetry is a 2D option (Dimension = 2: x the radius, "
                  "y the axis).");
      if (lower_corner[0] < 0.)
        bad_value("Grid/Lower corner",
                  prm.get("Lower corner"),
                  "with Axisymmetric = true x is the radius: the grid's "
                  "lower x must not be negative.");
      if (lower_corner[0] > 0.)
        return;
      // The grid reaches the axis: the radial displacement is zero there.
      const FaceCondition axis       = face_conditions[0];
      const bool          radial_set = axis == FaceCondition::roller ||
                              axis == FaceCondition::fixed ||
                              ((axis == FaceCondition::prescribed ||
                                axis == FaceCondition::prescribed_normal) &&
                               face_displacements[0][0] == 0.);
      if (!radial_set || face_has_region[0])
        bad_value("Grid/Condition x-",
                  prm.get("Condition x-"),
                  "the grid reaches the axis (lower x = 0), where the radial "
                  "displacement is zero: set 'Condition x-' to roller (or "
                  "fixed) on the whole face, without 'Region x-'.");
    }



    void
    MaterialPoints::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material points");
      prm.declare_entry("Basis",
                        "GIMP",
                        Patterns::Selection("GIMP|standard MPM"),
                        "Weighting between points and nodes: GIMP (the "
                        "shape function averaged over the point's domain) "
                        "or standard MPM (the shape function at the point).");
      prm.declare_entry("Update domains",
                        "true",
                        Patterns::Bool(),
                        "GIMP only: scale the domain half-lengths with the "
                        "stretch U of F = RU (true) or keep them (false).");
      prm.declare_entry(
        "Move points",
        "true",
        Patterns::Bool(),
        "true: the points move with the material through the grid (the "
        "material point method). false: each point stays where it was "
        "seeded, so the grid sees the material in its initial "
        "configuration, as a finite element analysis without mesh update "
        "does; the deformation gradient and the stress still accumulate, "
        "while the points' written displacement stays zero (the reactions "
        "and stresses carry the answer; no strength reduction). A "
        "reference for small displacements that separates the effect of "
        "the points' motion through the cells (with standard MPM the "
        "quadrature drifts as they move: doc/hard_cases.md) from the rest. "
        "Not with rigid bodies, which must meet the moving material.");
      prm.declare_entry("F-bar",
                        "false",
                        Patterns::Bool(),
                        "Against volumetric locking (Coombs et al. 2018): "
                        "each point's volume change is replaced by the "
                        "volume-weighted mean of the points of its body in "
                        "its cell at the start of the step, with the "
                        "consistent tangent (non-symmetric; it couples all "
                        "nodes those points touch).");
      prm.declare_entry(
        "Cell pressure unknowns",
        "false",
        Patterns::Bool(),
        "With F-bar: false gives the points of a body in a cell their mean "
        "volume change (one volume constraint per cell); true gives them "
        "one pressure instead, an unknown of the linear system per cell and "
        "body, each point taking the volume change at which its mean "
        "stress is that pressure, and their volume the cell's (Q1/P0 "
        "displacement-pressure). A frictional material needs it: with the "
        "mean volume change, points that dilate more lose pressure and "
        "strength. Costs a scalar Newton solve around each point's return "
        "map in every stress update.");
      prm.declare_entry(
        "Pressure jump stabilisation",
        "0",
        Patterns::Double(0.),
        "With cell pressure unknowns: the factor beta of the penalty on the "
        "jumps of the pressure between neighbouring cells of a body "
        "(against Q1/P0's checkerboard of cell pressures); 0 for none. "
        "Larger beta: smoother pressures, a larger departure from each "
        "cell's volume. (>= 0)");
      prm.declare_entry("Load imbalance threshold",
                        "1.2",
                        Patterns::Double(1.),
                        "On more than one process: when the process with "
                        "the most points holds more than this times the "
                        "mean, the grid is repartitioned with cells weighted "
                        "by their points (checked after seeding and after "
                        "every converged load step; >= 1).");
      prm.leave_subsection();
    }

    void
    MaterialPoints::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material points");
      basis                  = basis_type_from_string(prm.get("Basis"));
      update_domains         = prm.get_bool("Update domains");
      move_points            = prm.get_bool("Move points");
      f_bar                  = prm.get_bool("F-bar");
      cell_pressure_unknowns = prm.get_bool("Cell pressure unknowns");
      pressure_jump_stabilisation =
        prm.get_double("Pressure jump stabilisation");
      if (cell_pressure_unknowns && !f_bar)
        bad_value("Material points/Cell pressure unknowns",
                  prm.get("Cell pressure unknowns"),
                  "cell pressures need 'Material points/F-bar = true'");
      if (pressure_jump_stabilisation > 0. && !cell_pressure_unknowns)
        bad_value("Material points/Pressure jump stabilisation",
                  prm.get("Pressure jump stabilisation"),
                  "a stabilisation needs 'Material points/Cell pressure "
                  "unknowns = true' (or set it to 0)");
      load_imbalance_threshold = prm.get_double("Load imbalance threshold");
      prm.leave_subsection();
    }



    template <int dim>
    void
    All<dim>::parse_parameters(ParameterHandler &prm)
    {
      scene.parse_parameters(prm);
      grid.parse_parameters(prm);
      const unsigned int n_bodies = prm.get_integer("Number of bodies");
      bodies.resize(n_bodies);
      for (unsigned int k = 0; k < n_bodies; ++k)
        bodies[k].parse_parameters(prm, k + 1);
      rigid_bodies.resize(prm.get_integer("Number of rigid bodies"));
      for (unsigned int k = 0; k < rigid_bodies.size(); ++k)
        rigid_bodies[k].parse_parameters(prm, k + 1);
      material_points.parse_parameters(prm);
      prm.enter_subsection("Gravity");
      gravity_enabled = prm.get_bool("Enabled");
      // A scene without gravity need not give its acceleration (the
      // default, '0, -10', is a 2D one).
      gravity = Tensor<1, dim>();
      if (gravity_enabled)
        {
          const auto g = get_vector(prm, "Gravity", "Acceleration", dim);
          for (unsigned int d = 0; d < dim; ++d)
            gravity[d] = g[d];
        }
      prm.leave_subsection();
    }



    void
    declare_all(ParameterHandler &prm)
    {
      Scene::declare_parameters(prm);
      Grid<2>::declare_parameters(prm);
      prm.declare_entry("Number of bodies",
                        "1",
                        Patterns::Integer(1, impm::Body<2>::max_bodies),
                        "How many of the subsections Body 1 ... Body 4 the "
                        "scene uses (1 to 4).");
      impm::Body<2>::declare_parameters(prm);
      prm.declare_entry(
        "Number of rigid bodies",
        "0",
        Patterns::Integer(0, impm::RigidBody<2>::max_rigid_bodies),
        "How many of the subsections Rigid body 1 ... Rigid body 4 the "
        "scene uses (0 to 4): rigid shapes that move by a prescribed "
        "displacement and touch the material with a penalty contact.");
      impm::RigidBody<2>::declare_parameters(prm);
      MaterialPoints::declare_parameters(prm);
      EffectRegistry::declare_parameters(prm);
    }



    template struct Grid<2>;
    template struct Grid<3>;
    template struct All<2>;
    template struct All<3>;
  } // namespace Parameters
} // namespace impm
