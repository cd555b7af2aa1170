// Rigid contact's checks of a converged load step (RigidContact::
// refuse_step()) and the entries of subsection 'Rigid contact': a body
// that left the grid, a body that moved too far in one step (it may pass
// through material between the step's start and its end, where no probe
// sees it: issue 31's plate moved 1.25 m through a 1 m block in one step
// with zero force), and material points left inside a body (tunnelling).
#include <deal.II/base/mpi.h>

#include <impm/contact/rigid_contact.h>
#include <impm/system/load_step_system.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

namespace impm
{
  namespace
  {
    /** The smallest box holding @p corners. */
    template <int dim>
    std::pair<Point<dim>, Point<dim>>
    box_of(const std::vector<Point<dim>> &corners)
    {
      std::pair<Point<dim>, Point<dim>> box(corners[0], corners[0]);
      for (const Point<dim> &corner : corners)
        for (unsigned int d = 0; d < dim; ++d)
          {
            box.first[d]  = std::min(box.first[d], corner[d]);
            box.second[d] = std::max(box.second[d], corner[d]);
          }
      return box;
    }

    /** Whether @p box meets the box [@p lower, @p upper]. */
    template <int dim>
    bool
    meets(const std::pair<Point<dim>, Point<dim>> &box,
          const Point<dim>                        &lower,
          const Point<dim>                        &upper)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (box.second[d] < lower[d] || box.first[d] > upper[d])
          return false;
      return true;
    }

    /** The box [@p lower, @p upper] in words: [a, b] x [c, d]. */
    template <int dim>
    std::string
    in_words(const Point<dim> &lower, const Point<dim> &upper)
    {
      std::ostringstream out;
      for (unsigned int d = 0; d < dim; ++d)
        out << (d == 0 ? "" : " x ") << '[' << lower[d] << ", " << upper[d]
            << ']';
      return out.str();
    }
  } // namespace



  template <int dim>
  void
  RigidContact<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Maximum motion per step",
      "1",
      Patterns::Double(0.),
      "A converged load step in which a rigid body is displaced by more "
      "than this many cell sizes in one direction (its rotation is not "
      "limited) is cut like one that breaks 'Solver/Maximum point "
      "increment', so that no body passes through material between a "
      "step's start and its end, where no contact sees it; without "
      "'Solver/Step control' it stops the run (0: no limit). Every "
      "converged step is also checked for a material point left inside a "
      "body deeper than the contact lets a face in (cell size / 'Penalty "
      "factor'): such a step is cut too, and a rigid body that leaves the "
      "grid stops the run.");
  }



  template <int dim>
  std::vector<Point<dim>>
  RigidContact<dim>::moved_corners(const unsigned int    b,
                                   const Tensor<1, dim> &body_displacement,
                                   const Tensor<2, dim> &body_rotation) const
  {
    const RigidBody<dim>   &body = rigid_bodies[b];
    const auto              box  = body.bounding_box(Tensor<1, dim>());
    std::vector<Point<dim>> corners;
    for (unsigned int k = 0; k < (1u << dim); ++k)
      {
        Point<dim> corner;
        for (unsigned int d = 0; d < dim; ++d)
          corner[d] = (k >> d) & 1 ? box.second[d] : box.first[d];
        corners.push_back(body.rotation_centre + body_displacement +
                          body_rotation * (corner - body.rotation_centre));
      }
    return corners;
  }



  template <int dim>
  StepRefusal
  RigidContact<dim>::refuse_step(const MaterialPoints<dim> &material_points,
                                 const LoadStepSystem<dim> &system,
                                 const NodalVector         &increment) const
  {
    const auto &cartesian = grid.cartesian();
    for (unsigned int b = 0; b < rigid_bodies.size(); ++b)
      {
        const auto start =
          moved_corners(b, start_displacement[b], start_rotation[b]);
        const auto end = moved_corners(b, displacement[b], rotation[b]);
        const auto box = box_of(end);
        if (meets(box_of(start), cartesian.lower, cartesian.upper) &&
            !meets(box, cartesian.lower, cartesian.upper))
          return {rigid_bodies[b].name +
                    " leaves the grid in this step: its box " +
                    in_words(box.first, box.second) +
                    " m does not meet the grid " +
                    in_words(cartesian.lower, cartesian.upper) +
                    " m (a body outside the grid touches nothing; keep its "
                    "'Displacement' within the grid or enlarge the grid).",
                  false};
        // The translation over the step (a turning body's rotation is not
        // limited: a disc turning about its centre sweeps nothing, a wide
        // plate's corners sweep far from the material, equivalent_runs).
        double largest = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          largest =
            std::max(largest,
                     std::abs(displacement[b][d] - start_displacement[b][d]) /
                       cartesian.cell_size[d]);
        if (maximum_motion > 0. && largest > maximum_motion)
          {
            std::ostringstream out;
            out << rigid_bodies[b].name << " moves by " << largest
                << " cell sizes in this step, more than 'Rigid contact/"
                   "Maximum motion per step' = "
                << maximum_motion
                << " (it could pass through material unseen).";
            return {out.str(), true};
          }
      }
    return points_inside(material_points, system, increment);
  }



  template <int dim>
  StepRefusal
  RigidContact<dim>::points_inside(const MaterialPoints<dim> &material_points,
                                   const LoadStepSystem<dim> &system,
                                   const NodalVector         &increment) const
  {
    const auto &cell_size     = grid.cartesian().cell_size;
    double      smallest_cell = cell_size[0];
    for (unsigned int d = 1; d < dim; ++d)
      smallest_cell = std::min(smallest_cell, cell_size[d]);
    std::vector<std::pair<Point<dim>, Point<dim>>> boxes;
    for (unsigned int b = 0; b < rigid_bodies.size(); ++b)
      boxes.push_back(box_of(moved_corners(b, displacement[b], rotation[b])));
    // The deepest point whose whole domain is inside a body beyond the
    // contact's tolerance (the depth a face may have under the penalty, h /
    // alpha): its centre deeper than its domain's half-length and that, in
    // cell sizes. (A centre inside alone is not enough: a face over a box's
    // edge presses with its part under the body, and the point beside the
    // edge may come partly under it, contact_leaving_edge.)
    double       deepest = 0.;
    unsigned int body    = 0;
    Point<dim>   where;
    for (const auto &point : material_points.particles())
      {
        const PointStep<dim> &step = system.point_steps.of(point);
        const Point<dim>      x =
          point.get_location() + step.displacement(increment);
        const Tensor<1, dim> half_length =
          PointState<dim>(point.get_properties()).domain_half_length();
        double largest_half_length = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          largest_half_length = std::max(largest_half_length, half_length[d]);
        for (unsigned int b = 0; b < rigid_bodies.size(); ++b)
          {
            bool in_box = true;
            for (unsigned int d = 0; d < dim; ++d)
              in_box = in_box && x[d] >= boxes[b].first[d] &&
                       x[d] <= boxes[b].second[d];
            if (!in_box)
              continue;
            const double depth =
              (-rigid_bodies[b]
                  .proximity(x, displacement[b], rotation[b], nullptr)
                  .gap -
               largest_half_length) /
              smallest_cell;
            if (depth > 1. / rigid_bodies[b].penalty_factor && depth > deepest)
              std::tie(deepest, body, where) = std::make_tuple(depth, b, x);
          }
      }
    const MPI_Comm communicator = grid.get_triangulation().get_communicator();
    const auto     found = Utilities::MPI::min_max_avg(deepest, communicator);
    if (!(found.max > 0.))
      return {};
    const auto [b, x] = Utilities::MPI::broadcast(communicator,
                                                  std::make_pair(body, where),
                                                  found.max_index);
    std::ostringstream out;
    out << "the domain of the material point at (" << x << ") lies "
        << found.max << " cell sizes inside " << rigid_bodies[b].name
        << " after this step, deeper than the contact lets a face in ("
        << 1. / rigid_bodies[b].penalty_factor
        << "): the body passed into the material (tunnelling).";
    return {out.str(), true};
  }



#define IMPM_INSTANTIATE(dim)                                                  \
  template void RigidContact<dim>::declare_parameters(ParameterHandler &);     \
  template std::vector<Point<dim>> RigidContact<dim>::moved_corners(           \
    const unsigned int, const Tensor<1, dim> &, const Tensor<2, dim> &) const; \
  template StepRefusal RigidContact<dim>::refuse_step(                         \
    const MaterialPoints<dim> &,                                               \
    const LoadStepSystem<dim> &,                                               \
    const NodalVector &) const;                                                \
  template StepRefusal RigidContact<dim>::points_inside(                       \
    const MaterialPoints<dim> &,                                               \
    const LoadStepSystem<dim> &,                                               \
    const NodalVector &) const;
  IMPM_INSTANTIATE(2)
  IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE
} // namespace impm
