#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/core/boundary_selection.h>
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

      bool
      scales_with_load_factor() const override
      {
        return ramped;
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
                          "in plane strain; in axisymmetry the whole ring's "
                          "through the point) at the full load, one "
                          "component per dimension.");
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
        BoundarySelection<dim>::declare_parameters(prm, "loaded");
        prm.declare_entry("Traction",
                          "0, 0",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Traction in Pa (force per unit initial area) at "
                          "the full load, one component per dimension.");
      }

      explicit Traction(ParameterHandler &prm)
        : boundary(prm, "Traction")
        , traction(get_tensor<dim>(prm, "Traction", "Traction"))
      {}

      void
      initialize(const std::vector<MaterialPointInfo<dim>> &points,
                 const std::vector<Body<dim>>              &bodies,
                 const CartesianGrid<dim>                  &grid,
                 const MPI_Comm communicator) override
      {
        boundary.select(points, bodies, grid, communicator);
      }

      void
      add_face_forces(const std::vector<MaterialPointInfo<dim>> &points,
                      const double                               load_factor,
                      std::vector<FaceForce<dim>> &face_forces) const override
      {
        const auto &areas = boundary.areas();
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
            << boundary.description();
        if (boundary.n_points() > 0)
          out << " (" << boundary.n_points() << " points, area "
              << boundary.total_area() << ")";
        return out.str();
      }

    private:
      /** The part of the boundary loaded and its points. */
      BoundarySelection<dim> boundary;
      const Tensor<1, dim>   traction;
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
