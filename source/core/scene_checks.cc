#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/core/scene_checks.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace impm
{
  namespace SceneChecks
  {
    namespace
    {
      template <int dim>
      std::string
      box_string(const Point<dim> &lower, const Point<dim> &upper)
      {
        std::ostringstream out;
        out << "[" << lower << "] - [" << upper << "]";
        return out.str();
      }

      /** A length scale for comparisons: the grid's largest extent. */
      template <int dim>
      double
      grid_extent(const Parameters::Grid<dim> &grid)
      {
        double extent = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          extent =
            std::max(extent, grid.upper_corner[d] - grid.lower_corner[d]);
        return extent;
      }

      template <int dim>
      double
      cell_size(const Parameters::Grid<dim> &grid, const unsigned int d)
      {
        return (grid.upper_corner[d] - grid.lower_corner[d]) / grid.n_cells[d];
      }

      template <int dim>
      void
      check_bodies_inside(const Parameters::All<dim> &parameters)
      {
        const auto  &grid      = parameters.grid;
        const double tolerance = 1e-12 * grid_extent(grid);
        for (const auto &body : parameters.bodies)
          {
            const auto box = body.bounding_box();
            // A face with a roller may be a symmetry plane: a body may
            // cross it (the part beyond is cut off, a symmetric model).
            const auto symmetry_plane = [&](const unsigned int face) {
              return grid.face_conditions[face] ==
                       Parameters::FaceCondition::roller &&
                     !grid.face_has_region[face];
            };
            for (unsigned int d = 0; d < dim; ++d)
              if ((box.first[d] < grid.lower_corner[d] - tolerance &&
                   !symmetry_plane(2 * d)) ||
                  (box.second[d] > grid.upper_corner[d] + tolerance &&
                   !symmetry_plane(2 * d + 1)))
                throw InputError(
                  body.name + " (" + box_string(box.first, box.second) +
                  ") reaches outside the grid " +
                  box_string(grid.lower_corner, grid.upper_corner) + " in " +
                  Names::axis(d) +
                  ": a body must lie inside 'Grid/Lower corner' and "
                  "'Grid/Upper corner', or cross a face with a roller "
                  "('Grid/Condition', a symmetry plane).");
          }
      }

      /**
       * Every body has mass (a density of 0 makes the weight, the mass
       * matrix and the column's error 0 or NaN) and every rigid body moved
       * by a prescribed displacement reaches the grid at its start or its
       * end (one that does not never touches the material).
       */
      template <int dim>
      void
      check_densities_and_rigid_bodies(const Parameters::All<dim> &parameters)
      {
        for (const auto &body : parameters.bodies)
          if (!(body.density > 0.))
            {
              std::ostringstream value;
              value << body.density;
              throw InputError("'" + body.name + "/Density' = " + value.str() +
                               ": a body needs a density above 0.");
            }
        const auto &grid = parameters.grid;
        if (!parameters.material_points.move_points &&
            !parameters.rigid_bodies.empty())
          throw InputError(
            "'Material points/Move points' = false with a rigid body: a "
            "rigid body moves through the grid and must meet the material "
            "where it is, so the points must move (set it to true).");
        for (const auto &rigid_body : parameters.rigid_bodies)
          {
            if (rigid_body.get_shape().needs_axisymmetry() &&
                !grid.axisymmetric)
              throw InputError(rigid_body.name +
                               "/Shape = cone in 2D is the meridian plane of "
                               "a cone: it needs 'Grid/Axisymmetric' = true "
                               "(in plane strain, a polygon).");
            // A force-driven body's path is not known in advance (checked
            // when contact starts).
            bool force_driven = false;
            for (unsigned int d = 0; d < dim; ++d)
              force_driven = force_driven || rigid_body.is_force_driven(d);
            if (force_driven)
              continue;
            // The boxes at the start and at full displacement: a body that
            // lies outside the grid in both never meets the material.
            const auto start = rigid_body.bounding_box(Tensor<1, dim>());
            const auto end =
              rigid_body.bounding_box(rigid_body.displacement, 1.);
            for (unsigned int d = 0; d < dim; ++d)
              if (std::max(start.second[d], end.second[d]) <
                    grid.lower_corner[d] ||
                  std::min(start.first[d], end.first[d]) > grid.upper_corner[d])
                throw InputError(
                  rigid_body.name + " (" +
                  box_string(start.first, start.second) +
                  ") lies outside the grid " +
                  box_string(grid.lower_corner, grid.upper_corner) + " in " +
                  Names::axis(d) +
                  " and its 'Displacement' does not bring it in: a rigid "
                  "body must reach the grid to touch the material.");
          }
      }

      /**
       * No node both held at zero and moved: two adjacent faces without
       * regions share the nodes of their common edge, and one that holds a
       * component at 0 (roller, fixed, normal only) contradicts one that
       * prescribes a nonzero displacement of it.
       */
      template <int dim>
      void
      check_fixed_and_prescribed(const Parameters::Grid<dim> &grid)
      {
        // 'prescribed normal' moves the face's normal component only: a
        // tangential one given with it would be dropped without a word.
        for (unsigned int f = 0; f < 2 * dim; ++f)
          if (grid.face_conditions[f] ==
              Parameters::FaceCondition::prescribed_normal)
            for (unsigned int c = 0; c < dim; ++c)
              if (c != f / 2 && grid.face_displacements[f][c] != 0.)
                throw InputError(
                  "'Grid/Displacement " + Names::face(f) + "' has a " +
                  Names::axis(c) + " component, which 'Grid/Condition " +
                  Names::face(f) +
                  "' = 'prescribed normal' does not move (it moves the " +
                  Names::axis(f / 2) +
                  " component only): set it to 0, or use 'prescribed'.");
        for (unsigned int f = 0; f < 2 * dim; ++f)
          for (unsigned int g = 0; g < 2 * dim; ++g)
            if (f / 2 != g / 2 && !grid.face_has_region[f] &&
                !grid.face_has_region[g] &&
                !Parameters::is_prescribed(grid.face_conditions[f]) &&
                Parameters::is_prescribed(grid.face_conditions[g]))
              for (unsigned int c = 0; c < dim; ++c)
                if (Parameters::constrains(grid.face_conditions[f], f, c) &&
                    Parameters::constrains(grid.face_conditions[g], g, c) &&
                    grid.face_displacements[g][c] != 0.)
                  throw InputError(
                    "The nodes on the edge of grid faces " + Names::face(f) +
                    " and " + Names::face(g) + " are both held ('Grid/" +
                    "Condition " + Names::face(f) + "' holds their " +
                    Names::axis(c) +
                    " displacement at 0) and moved ('Grid/Condition " +
                    Names::face(g) +
                    "' prescribes it): give one of the "
                    "faces a 'Region' that leaves the edge out, or a "
                    "condition that does not act on " +
                    Names::axis(c) + ".");
      }

      /**
       * Whether the region of face @p face holds a node of the face.
       */
      template <int dim>
      bool
      region_holds_a_node(const Parameters::Grid<dim> &grid,
                          const unsigned int           face)
      {
        const auto        &region    = grid.face_regions[face];
        const unsigned int axis      = face / 2;
        const double       tolerance = 1e-10 * grid_extent(grid);
        const double       plane =
          face % 2 == 0 ? grid.lower_corner[axis] : grid.upper_corner[axis];
        if (plane < region.first[axis] - tolerance ||
            plane > region.second[axis] + tolerance)
          return false;
        for (unsigned int d = 0; d < dim; ++d)
          if (d != axis)
            {
              const double h = cell_size(grid, d);
              // The first node at or above the region's lower bound.
              const double first = std::ceil(
                (region.first[d] - grid.lower_corner[d] - tolerance) / h);
              const double node =
                grid.lower_corner[d] + std::max(0., first) * h;
              if (first > grid.n_cells[d] ||
                  node > region.second[d] + tolerance)
                return false;
            }
        return true;
      }

      template <int dim>
      void
      check_face_regions(const Parameters::Grid<dim> &grid)
      {
        for (unsigned int f = 0; f < 2 * dim; ++f)
          if (grid.face_has_region[f] &&
              grid.face_conditions[f] != Parameters::FaceCondition::none &&
              !region_holds_a_node(grid, f))
            throw InputError(
              "'Grid/Region " + Names::face(f) + "' = " +
              box_string(grid.face_regions[f].first,
                         grid.face_regions[f].second) +
              " holds no node of the grid face " + Names::face(f) +
              ", so 'Grid/Condition " + Names::face(f) +
              "' would hold nothing: the region must contain the face's "
              "plane and at least one of its nodes.");
      }

      /**
       * Whether face @p face, where its condition acts, is within a cell
       * of some body, so that the material touches the face's nodes.
       */
      template <int dim>
      bool
      face_touches_material(const Parameters::All<dim> &parameters,
                            const unsigned int          face)
      {
        const auto        &grid = parameters.grid;
        const unsigned int axis = face / 2;
        const double       plane =
          face % 2 == 0 ? grid.lower_corner[axis] : grid.upper_corner[axis];
        for (const auto &body : parameters.bodies)
          {
            const auto box = body.bounding_box();
            // (A body that crosses the face, a symmetry plane, touches
            // it.)
            bool touches = (face % 2 == 0 ? box.first[axis] - plane :
                                            plane - box.second[axis]) <
                           cell_size(grid, axis) * (1. + 1e-10);
            if (grid.face_has_region[face])
              for (unsigned int d = 0; d < dim; ++d)
                if (d != axis)
                  touches = touches &&
                            box.second[d] > grid.face_regions[face].first[d] -
                                              cell_size(grid, d) &&
                            box.first[d] < grid.face_regions[face].second[d] +
                                             cell_size(grid, d);
            if (touches)
              return true;
          }
        return false;
      }

      /**
       * The memory available to the run: the sum over its machines of
       * MemAvailable (Linux), counted once per machine; 0 if unknown.
       */
      double
      available_memory(const MPI_Comm communicator)
      {
        MPI_Comm machine;
        MPI_Comm_split_type(
          communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &machine);
        const bool first_on_machine =
          Utilities::MPI::this_mpi_process(machine) == 0;
        MPI_Comm_free(&machine);
        double bytes = 0.;
        if (first_on_machine)
          {
            std::ifstream meminfo("/proc/meminfo");
            std::string   key;
            double        kilobytes;
            std::string   unit;
            while (meminfo >> key >> kilobytes >> unit)
              if (key == "MemAvailable:")
                bytes = kilobytes * 1024.;
          }
        return Utilities::MPI::sum(bytes, communicator);
      }

      /** The estimated peak memory of a run, with the counts behind it. */
      struct MemoryEstimate
      {
        double n_cells  = 0.;
        double n_points = 0.;
        double bytes    = 0.;
      };



      template <int dim>
      MemoryEstimate
      estimate_memory(const Parameters::All<dim> &parameters)
      {
        // Peak resident memory measured on this project's runs (Release):
        // per cell of the grid about 0.9 kB in 2D and 1.7 kB in 3D (almost
        // empty grids, doc/benchmarks/reliability.md), per material
        // point 2.7 kB in 2D (the 10^6-point collapse, doc/benchmarks/
        // scaling.md); per 3D point 5.0 kB at 884,736 points and 7.5 kB
        // at 110,592 (the 3D benchmark on two processes, less the grid and
        // the processes' libraries, ibid.), taken at 8 kB.
        const double   bytes_per_cell  = dim == 2 ? 0.9e3 : 1.7e3;
        const double   bytes_per_point = dim == 2 ? 2.7e3 : 8e3;
        MemoryEstimate estimate;
        estimate.n_cells   = 1.;
        double cell_volume = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            estimate.n_cells *= parameters.grid.n_cells[d];
            cell_volume *= cell_size(parameters.grid, d);
          }
        for (const auto &body : parameters.bodies)
          estimate.n_points += body.volume() / cell_volume *
                               std::pow(body.points_per_direction, dim);
        estimate.bytes = estimate.n_cells * bytes_per_cell +
                         estimate.n_points * bytes_per_point;
        return estimate;
      }
    } // namespace



    template <int dim>
    void
    check(const Parameters::All<dim> &parameters, const MPI_Comm communicator)
    {
      // The memory first: a grid too large for the machine would stop in
      // p4est long before any other check could speak.
      const MemoryEstimate estimate  = estimate_memory(parameters);
      const double         available = available_memory(communicator);
      if (available > 0. && estimate.bytes > available)
        {
          std::ostringstream message;
          message.precision(3);
          message << "The scene needs about " << bytes_in_words(estimate.bytes)
                  << " (" << estimate.n_cells << " cells, " << estimate.n_points
                  << " material points), more than the "
                  << bytes_in_words(available) << " available to the "
                  << Utilities::MPI::n_mpi_processes(communicator)
                  << " process(es): use fewer cells ('Grid/Number of "
                     "cells') or points, or more machines.";
          throw InputError(message.str());
        }
      check_bodies_inside(parameters);
      check_densities_and_rigid_bodies(parameters);
      check_fixed_and_prescribed(parameters.grid);
      check_face_regions(parameters.grid);
    }



    template <int dim>
    void
    check_supports(const Parameters::All<dim>              &parameters,
                   const std::function<bool(unsigned int)> &held_elsewhere)
    {
      const auto &grid = parameters.grid;
      for (unsigned int component = 0; component < dim; ++component)
        {
          // In axisymmetry a radial translation stretches the rings: their
          // hoop stiffness holds the material radially (a hollow cylinder
          // needs no radial support).
          bool held =
            held_elsewhere(component) || (grid.axisymmetric && component == 0);
          for (unsigned int f = 0; f < 2 * dim && !held; ++f)
            held =
              Parameters::constrains(grid.face_conditions[f], f, component) &&
              face_touches_material(parameters, f);
          if (!held)
            throw InputError(
              "Nothing holds the material in the " + Names::axis(component) +
              " direction: no 'Grid/Condition' that fixes " +
              Names::axis(component) +
              " displacements acts on a grid face within one cell of a "
              "body, so the system would be singular. Set, e.g., "
              "'Grid/Condition " +
              Names::face(2 * component) +
              "' to roller or fixed on a face the material touches.");
        }
    }



    template <int dim>
    void
    check_motion_start(const Parameters::All<dim> &parameters,
                       const Parameters::Time     &time)
    {
      if (!time.in_time())
        return;
      const double start_factor = LoadPath(time).load_factor(0.);
      if (start_factor == 0.)
        return;
      std::string moved;
      for (unsigned int f = 0; f < 2 * dim && moved.empty(); ++f)
        if (Parameters::is_prescribed(parameters.grid.face_conditions[f]) &&
            parameters.grid.face_displacements[f].norm() > 0.)
          moved = "the displacement of face " + Names::face(f) +
                  " ('Grid/Condition " + Names::face(f) + "')";
      for (unsigned int k = 0;
           k < parameters.rigid_bodies.size() && moved.empty();
           ++k)
        if (parameters.rigid_bodies[k].displacement_at(1.).norm() > 0. ||
            parameters.rigid_bodies[k].rotates())
          moved = "the motion of Rigid body " + std::to_string(k + 1);
      if (!moved.empty())
        throw InputError(
          "Parameter 'Time/Load factor' = '" + time.load_factor + "' is " +
          number_text(start_factor) + " at t = 0, but " + moved +
          " starts from the scene's initial state and follows the factor's "
          "change: its share at t = 0 would be lost. Give a load factor "
          "that is 0 at t = 0 (e.g. 't < 0.01 ? t/0.01 : 1' for a load "
          "applied within 0.01 s).");
    }



    template void
    check_motion_start<2>(const Parameters::All<2> &, const Parameters::Time &);
    template void
    check_motion_start<3>(const Parameters::All<3> &, const Parameters::Time &);
    template void
    check_supports<2>(const Parameters::All<2> &,
                      const std::function<bool(unsigned int)> &);
    template void
    check_supports<3>(const Parameters::All<3> &,
                      const std::function<bool(unsigned int)> &);



    template void
    check<2>(const Parameters::All<2> &, const MPI_Comm);
    template void
    check<3>(const Parameters::All<3> &, const MPI_Comm);
  } // namespace SceneChecks
} // namespace impm
