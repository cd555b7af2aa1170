// The seeding's helpers of MaterialPoints: a point's initial stress (zero
// or geostatic, checked inside the yield surface) and the check that every
// body holds points. The seeding itself is in material_points.cc.
#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/points/material_points.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace impm
{
  template <int dim>
  void
  MaterialPoints<dim>::set_initial_stress(
    const Body<dim>     &body,
    const Point<dim>    &position,
    const double         g,
    std::vector<double> &properties,
    std::string         &outside_yield_surface) const
  {
    const MutablePointState<dim> state{ArrayView<double>(properties)};
    // The declared state (material and couplings) starts at zero; the
    // body's material then sets its own.
    const unsigned int first = property_layout.material_state_first();
    std::fill(properties.begin() + first, properties.end(), 0.);
    const ArrayView<double> own_state(properties.data() + first,
                                      body.material->n_state_entries());
    if (body.initial_stress.geostatic)
      {
        const SymmetricTensor<2, 3> stress =
          body.geostatic_stress(position, g, bodies);
        SymmetricTensor<2, 3> elastic_strain;
        try
          {
            elastic_strain = body.material->elastic_strain_for_stress(stress);
          }
        catch (const InputError &error)
          {
            // A stress the elastic law cannot reach, found on this process
            // only: reported with the others, on every process.
            if (outside_yield_surface.empty())
              {
                std::ostringstream message;
                message << body.name << " at (" << position
                        << "): " << error.what();
                outside_yield_surface = message.str();
              }
            elastic_strain = unit_symmetric_tensor<3>();
          }
        state.set_kirchhoff_stress(stress);
        state.set_elastic_left_cauchy_green(elastic_strain);
        body.material->initialize_state(stress, own_state);
        // The start must lie inside the yield surface.
        ConstitutiveUpdate start;
        body.material->update(unit_symmetric_tensor<3>(),
                              elastic_strain,
                              ArrayView<const double>(own_state.data(),
                                                      own_state.size()),
                              start);
        if (start.plastic && outside_yield_surface.empty())
          {
            std::ostringstream message;
            message << body.name << ": the geostatic stress with K0 = "
                    << body.initial_stress.k0 << " lies outside the "
                    << "yield surface of its material at (" << position
                    << "), vertical stress " << stress[dim - 1][dim - 1]
                    << " Pa (" << body.material->description()
                    << "); choose a K0 nearer 1 or a stronger "
                       "material.";
            outside_yield_surface = message.str();
          }
      }
    else
      {
        state.set_kirchhoff_stress(SymmetricTensor<2, 3>());
        state.set_elastic_left_cauchy_green(unit_symmetric_tensor<3>());
        body.material->initialize_state(SymmetricTensor<2, 3>(), own_state);
      }
  }



  template <int dim>
  void
  MaterialPoints<dim>::check_bodies_hold_points(
    const std::vector<unsigned int> &n_local) const
  {
    std::vector<unsigned int> points_of_body(n_local);
    Utilities::MPI::sum(n_local, communicator, points_of_body);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (points_of_body[b] == 0)
        {
          const auto         box = bodies[b].bounding_box();
          std::ostringstream message;
          message << bodies[b].name << " ([" << box.first << "] - ["
                  << box.second << "]) holds no material point: none of its ";
          for (unsigned int d = 0; d < dim; ++d)
            message << (d ? " x " : "") << bodies[b].points_per_direction;
          message << " point positions per cell lies inside it; enlarge it "
                     "or raise its 'Points per cell direction'.";
          throw InputError(message.str());
        }
  }



  template void
  MaterialPoints<2>::set_initial_stress(const Body<2> &,
                                        const Point<2> &,
                                        const double,
                                        std::vector<double> &,
                                        std::string &) const;
  template void
  MaterialPoints<3>::set_initial_stress(const Body<3> &,
                                        const Point<3> &,
                                        const double,
                                        std::vector<double> &,
                                        std::string &) const;
  template void
  MaterialPoints<2>::check_bodies_hold_points(
    const std::vector<unsigned int> &) const;
  template void
  MaterialPoints<3>::check_bodies_hold_points(
    const std::vector<unsigned int> &) const;
} // namespace impm
