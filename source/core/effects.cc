#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/core/effects.h>
#include <impm/core/parameters.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace impm
{
  template <int dim>
  void
  ForceEffect<dim>::initialize(const std::vector<MaterialPointInfo<dim>> &,
                               const std::vector<Body<dim>> &,
                               const CartesianGrid<dim> &,
                               const MPI_Comm)
  {}



  namespace EffectRegistry
  {
    void
    declare_enabled(ParameterHandler &prm, const bool enabled_by_default)
    {
      prm.declare_entry("Enabled",
                        enabled_by_default ? "true" : "false",
                        Patterns::Bool(),
                        "Whether the scene applies this effect. An "
                        "effect that is off is not created and costs "
                        "nothing.");
    }

    void
    declare_parameters(ParameterHandler &prm)
    {
      for (const auto &entry : ForceEffectList<2>::entries())
        {
          prm.enter_subsection(entry.name);
          entry.declare_parameters(prm);
          prm.leave_subsection();
        }
    }

    template <int dim>
    std::vector<std::unique_ptr<ForceEffect<dim>>>
    create_enabled(ParameterHandler &prm)
    {
      std::vector<std::unique_ptr<ForceEffect<dim>>> effects;
      for (const auto &entry : ForceEffectList<dim>::entries())
        {
          prm.enter_subsection(entry.name);
          if (prm.get_bool("Enabled"))
            effects.push_back(entry.create(prm));
          prm.leave_subsection();
        }
      return effects;
    }
  } // namespace EffectRegistry



  namespace
  {
    /** Format a tensor as "a, b(, c)". */
    template <int dim>
    std::string
    to_string(const Tensor<1, dim> &t)
    {
      std::ostringstream out;
      for (unsigned int d = 0; d < dim; ++d)
        out << (d ? ", " : "") << t[d];
      return out.str();
    }

    template <int dim>
    Tensor<1, dim>
    get_tensor(ParameterHandler  &prm,
               const std::string &section,
               const std::string &entry)
    {
      const auto     values = Parameters::get_vector(prm, section, entry, dim);
      Tensor<1, dim> t;
      for (unsigned int d = 0; d < dim; ++d)
        t[d] = values[d];
      return t;
    }



    /**
     * @brief The body force of the points' masses, m g: ramped with the
     * load factor, or in full from the first load step (for a geostatic
     * start).
     */
    template <int dim>
    class Gravity : public ForceEffect<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Acceleration",
                          "0, -10",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Gravitational acceleration in m/s^2, one "
                          "component per dimension.");
        prm.declare_entry("Ramped",
                          "true",
                          Patterns::Bool(),
                          "true: the weight grows with the load factor over "
                          "the load steps; false: it acts in full from the "
                          "first load step (a body with a geostatic initial "
                          "stress is in equilibrium with it).");
      }

      explicit Gravity(ParameterHandler &prm)
        : acceleration(get_tensor<dim>(prm, "Gravity", "Acceleration"))
        , ramped(prm.get_bool("Ramped"))
      {}

      void
      add_forces(const std::vector<MaterialPointInfo<dim>> &points,
                 const double                               load_factor,
                 std::vector<Tensor<1, dim>> &forces) const override
      {
        const double factor = ramped ? load_factor : 1.;
        for (unsigned int p = 0; p < points.size(); ++p)
          forces[p] += (factor * points[p].mass) * acceleration;
      }

      Tensor<1, dim>
      acceleration_from_the_start() const override
      {
        return ramped ? Tensor<1, dim>() : acceleration;
      }

      std::string
      description() const override
      {
        return "gravity: acceleration (" + to_string(acceleration) + ") m/s^2" +
               (ramped ? "" : ", in full from the first step");
      }

    private:
      const Tensor<1, dim> acceleration;
      const bool           ramped;
    };



    /**
     * @brief Forces on the points nearest to given positions.
     */
    template <int dim>
    class PointLoad : public ForceEffect<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Positions",
                          "0, 0",
                          Patterns::Anything(),
                          "Where the loads act: 'x, y; x, y; ...'. Each "
                          "load acts on the material point nearest to its "
                          "position at the start.");
        prm.declare_entry("Force",
                          "0, 0",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "The force of each load in N (per unit thickness "
                          "in 2D) at the full load, one component per "
                          "dimension.");
      }

      explicit PointLoad(ParameterHandler &prm)
        : force(get_tensor<dim>(prm, "Point load", "Force"))
      {
        for (const auto &xyz :
             Parameters::get_point_list(prm, "Point load", "Positions", dim))
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = xyz[d];
            positions.push_back(p);
          }
      }

      void
      initialize(const std::vector<MaterialPointInfo<dim>> &points,
                 const std::vector<Body<dim>> &,
                 const CartesianGrid<dim> &grid,
                 const MPI_Comm            communicator) override
      {
        loaded_ids.clear();
        double largest_cell = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          largest_cell = std::max(largest_cell, grid.cell_size[d]);
        for (const auto &position : positions)
          {
            if (!grid.contains(position))
              {
                std::ostringstream message;
                message << "'Point load/Positions': (" << position
                        << ") lies outside the grid [" << grid.lower << "] - ["
                        << grid.upper << "].";
                throw InputError(message.str());
              }
            std::pair<double, std::uint64_t> nearest(
              std::numeric_limits<double>::max(), 0);
            for (const auto &point : points)
              nearest = std::min(nearest,
                                 std::make_pair(point.initial_position.distance(
                                                  position),
                                                point.id));
            const auto all = Utilities::MPI::all_gather(communicator, nearest);
            const auto closest = *std::min_element(all.begin(), all.end());
            if (closest.first > largest_cell)
              {
                std::ostringstream message;
                message << "'Point load/Positions': (" << position << ") is "
                        << closest.first
                        << " m from the nearest material point; a load must "
                           "act within one cell ("
                        << largest_cell << " m) of the material.";
                throw InputError(message.str());
              }
            loaded_ids.push_back(closest.second);
          }
      }

      void
      add_forces(const std::vector<MaterialPointInfo<dim>> &points,
                 const double                               load_factor,
                 std::vector<Tensor<1, dim>> &forces) const override
      {
        for (unsigned int p = 0; p < points.size(); ++p)
          for (const auto id : loaded_ids)
            if (points[p].id == id)
              forces[p] += load_factor * force;
      }

      std::string
      description() const override
      {
        std::ostringstream out;
        out << "point load: (" << to_string(force) << ") N at";
        for (unsigned int i = 0; i < positions.size(); ++i)
          out << " (" << positions[i] << ")"
              << (loaded_ids.size() > i ?
                    " -> point " + std::to_string(loaded_ids[i]) :
                    std::string());
        return out.str();
      }

    private:
      const Tensor<1, dim>       force;
      std::vector<Point<dim>>    positions;
      std::vector<std::uint64_t> loaded_ids;
    };



    /**
     * @brief A traction (force per unit initial area) on one side of a
     * body's boundary, optionally within a box. The boundary points are
     * found once, from the points' lattice: a point is on the boundary in
     * direction +-e_d when its neighbouring lattice site in that direction
     * lies outside the body.
     */
    template <int dim>
    class Traction : public ForceEffect<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Body",
                          "1",
                          Patterns::Integer(1, Body<dim>::max_bodies),
                          "The body whose boundary is loaded (1 to 4).");
        prm.declare_entry("Boundary",
                          "y+",
                          Patterns::Selection("x-|x+|y-|y+|z-|z+|region"),
                          "The side of the body's boundary that is loaded, "
                          "by its outward normal: x-, x+, y-, y+ (, z-, z+); "
                          "or 'region': every part of the boundary inside "
                          "the region, whatever its normal (slanted sides).");
        prm.declare_entry("Region lower corner",
                          "",
                          Patterns::List(Patterns::Double(), 0, 3),
                          "If given, only points initially inside this box "
                          "are loaded (empty: the whole side; required for "
                          "Boundary = region).");
        prm.declare_entry("Region upper corner",
                          "",
                          Patterns::List(Patterns::Double(), 0, 3),
                          "Upper corner of that box.");
        prm.declare_entry("Traction",
                          "0, 0",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Traction in Pa (force per unit initial area) at "
                          "the full load, one component per dimension.");
      }

      explicit Traction(ParameterHandler &prm)
        : body(prm.get_integer("Body") - 1)
        , by_region(prm.get("Boundary") == "region")
        , boundary(by_region ? 0 : Names::face_from_name(prm.get("Boundary")))
        , traction(get_tensor<dim>(prm, "Traction", "Traction"))
      {
        const auto lower = Parameters::get_optional_vector(
          prm, "Traction", "Region lower corner", dim);
        const auto upper = Parameters::get_optional_vector(
          prm, "Traction", "Region upper corner", dim);
        if (lower.size() != upper.size())
          Parameters::bad_value("Traction/Region upper corner",
                                prm.get("Region upper corner"),
                                "give both corners of the region, or "
                                "neither.");
        for (unsigned int d = 0; d < lower.size(); ++d)
          {
            region_lower[d] = lower[d];
            region_upper[d] = upper[d];
          }
        has_region = !lower.empty();
        if (by_region && !has_region)
          Parameters::bad_value("Traction/Boundary",
                                "region",
                                "give the region's corners ('Region lower "
                                "corner', 'Region upper corner').");
        if (boundary >= 2 * dim)
          Parameters::bad_value("Traction/Boundary",
                                prm.get("Boundary"),
                                "in " + std::to_string(dim) +
                                  "D only x-, x+, y-, y+" +
                                  (dim == 3 ? ", z-, z+" : "") + " or region.");
      }

      void
      initialize(const std::vector<MaterialPointInfo<dim>> &points,
                 const std::vector<Body<dim>>              &bodies,
                 const CartesianGrid<dim>                  &grid,
                 const MPI_Comm communicator) override
      {
        if (body >= bodies.size())
          throw InputError(
            "Parameter 'Traction/Body' = " + std::to_string(body + 1) +
            " is not allowed: the scene has " + std::to_string(bodies.size()) +
            " bodies.");
        const Body<dim> &loaded = bodies[body];
        Tensor<1, dim>   spacing;
        for (unsigned int d = 0; d < dim; ++d)
          spacing[d] = grid.cell_size[d] / loaded.points_per_direction;
        // The area of a lattice face normal to each axis.
        std::array<double, dim> lattice_face;
        for (unsigned int a = 0; a < dim; ++a)
          {
            lattice_face[a] = 1.;
            for (unsigned int d = 0; d < dim; ++d)
              if (d != a)
                lattice_face[a] *= spacing[d];
          }

        const auto in_region = [&](const Point<dim> &x) {
          bool inside = true;
          if (has_region)
            for (unsigned int d = 0; d < dim; ++d)
              inside =
                inside && x[d] >= region_lower[d] && x[d] <= region_upper[d];
          return inside;
        };
        // The boundary points (in the region): those whose lattice
        // neighbour across a loaded face is outside the body or the grid,
        // with those faces (a bit per face).
        std::vector<std::pair<std::uint64_t, Point<dim>>> boundary_points;
        std::vector<unsigned int>                         open_faces;
        for (const auto &point : points)
          {
            if (point.body != body || !in_region(point.initial_position))
              continue;
            unsigned int faces = 0;
            for (unsigned int f = 0; f < 2 * dim; ++f)
              {
                if (!by_region && f != boundary)
                  continue;
                Point<dim> neighbour = point.initial_position;
                neighbour[Names::face_axis(f)] +=
                  Names::face_sign(f) * spacing[Names::face_axis(f)];
                if (!loaded.contains(neighbour) || !grid.contains(neighbour))
                  faces |= 1u << f;
              }
            if (faces != 0)
              {
                boundary_points.emplace_back(point.id, point.initial_position);
                open_faces.push_back(faces);
              }
          }
        // Points move between processes during the run: every process
        // keeps every loaded point. In the order of the ids, so that ties
        // go the same way on any number of processes.
        std::vector<std::pair<std::pair<std::uint64_t, Point<dim>>, unsigned>>
          local;
        for (unsigned int k = 0; k < boundary_points.size(); ++k)
          local.emplace_back(boundary_points[k], open_faces[k]);
        auto gathered = Utilities::MPI::all_gather(communicator, local);
        local.clear();
        for (const auto &part : gathered)
          local.insert(local.end(), part.begin(), part.end());
        std::sort(local.begin(), local.end(), [](const auto &a, const auto &b) {
          return a.first.first < b.first.first;
        });

        // Each point carries the part of the true boundary nearest to it:
        // the boundary is cut at the lattice lines (a sphere in zones and
        // sectors) and each piece goes to the nearest boundary point, on
        // the face of its domain that the piece's normal points through
        // most, so the loads add up to the traction times the true length
        // or area. Where the body has no pieces (a box in 3D) each point
        // carries its open lattice faces, which are exact.
        areas.clear();
        const std::vector<typename Body<dim>::BoundaryPiece> pieces =
          local.empty() ? std::vector<typename Body<dim>::BoundaryPiece>() :
          by_region     ? loaded.boundary_partition(grid.lower, spacing) :
                          loaded.boundary_pieces(Names::face_axis(boundary),
                                             Names::face_sign(boundary),
                                             grid.lower,
                                             spacing);
        if (pieces.empty())
          for (const auto &[point, faces] : local)
            for (unsigned int f = 0; f < 2 * dim; ++f)
              if (faces & (1u << f))
                areas[point.first][f] += lattice_face[Names::face_axis(f)];
        for (const auto &piece : pieces)
          {
            if (!in_region(piece.midpoint))
              continue;
            const auto nearest = std::min_element(
              local.begin(), local.end(), [&](const auto &a, const auto &b) {
                return a.first.second.distance_square(piece.midpoint) <
                       b.first.second.distance_square(piece.midpoint);
              });
            unsigned int axis = 0;
            for (unsigned int d = 1; d < dim; ++d)
              if (std::abs(piece.normal[d]) > std::abs(piece.normal[axis]))
                axis = d;
            const unsigned int face =
              by_region ? 2 * axis + (piece.normal[axis] > 0. ? 1 : 0) :
                          boundary;
            areas[nearest->first.first][face] += piece.size;
          }
        n_points = areas.size();
        if (n_points == 0)
          throw InputError(
            "Traction: no material point of Body " + std::to_string(body + 1) +
            " lies on its " +
            (by_region ? std::string("boundary") :
                         std::string(Names::face(boundary)) + " boundary") +
            (has_region ? " inside the region" : "") + ".");
        total_area = 0.;
        for (const auto &entry : areas)
          for (const double area : entry.second)
            total_area += area;
      }

      void
      add_face_forces(const std::vector<MaterialPointInfo<dim>> &points,
                      const double                               load_factor,
                      std::vector<FaceForce<dim>> &face_forces) const override
      {
        for (unsigned int p = 0; p < points.size(); ++p)
          {
            const auto area = areas.find(points[p].id);
            if (area != areas.end())
              for (unsigned int f = 0; f < 2 * dim; ++f)
                if (area->second[f] != 0.)
                  face_forces.push_back(
                    {p,
                     Names::face_axis(f),
                     Names::face_sign(f),
                     (load_factor * area->second[f]) * traction});
          }
      }

      std::string
      description() const override
      {
        std::ostringstream out;
        out << "traction: (" << to_string(traction) << ") Pa on the "
            << (by_region ? std::string("boundary in the region") :
                            std::string(Names::face(boundary)) + " side")
            << " of Body " << body + 1;
        if (n_points > 0)
          out << " (" << n_points << " points, area " << total_area << ")";
        return out.str();
      }

    private:
      const unsigned int body;
      /** Boundary = region: every side inside the region. */
      const bool           by_region;
      const unsigned int   boundary;
      const Tensor<1, dim> traction;
      Point<dim>           region_lower;
      Point<dim>           region_upper;
      bool                 has_region = false;
      /** Per loaded point: the area it carries on each face of its domain. */
      std::unordered_map<std::uint64_t, std::array<double, 2 * dim>> areas;
      unsigned int n_points   = 0;
      double       total_area = 0.;
    };
  } // namespace

  IMPM_REGISTER_FORCE_EFFECT(Gravity, "Gravity", true)
  IMPM_REGISTER_FORCE_EFFECT(PointLoad, "Point load", false)
  IMPM_REGISTER_FORCE_EFFECT(Traction, "Traction", false)

  template <int dim>
  void
  ForceEffect<dim>::add_forces(const std::vector<MaterialPointInfo<dim>> &,
                               const double,
                               std::vector<Tensor<1, dim>> &) const
  {}



  template <int dim>
  void
  ForceEffect<dim>::add_face_forces(const std::vector<MaterialPointInfo<dim>> &,
                                    const double,
                                    std::vector<FaceForce<dim>> &) const
  {}



  template class ForceEffect<2>;
  template class ForceEffect<3>;
  namespace EffectRegistry
  {
    template std::vector<std::unique_ptr<ForceEffect<2>>>
    create_enabled<2>(ParameterHandler &);
    template std::vector<std::unique_ptr<ForceEffect<3>>>
    create_enabled<3>(ParameterHandler &);
  } // namespace EffectRegistry
} // namespace impm
