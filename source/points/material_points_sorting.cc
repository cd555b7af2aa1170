// The points sorted into the cells and processes of their new positions
// (MaterialPoints::sort_into_cells()), and the check that spares deal.II's
// sort when no point has left its cell.
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/points/material_points.h>

#include <string>

namespace impm
{
  template <int dim>
  bool
  MaterialPoints<dim>::all_inside_their_cells() const
  {
    // A point counts as inside only when it is clear of its cell's faces
    // by 1e-10 of the cell: deal.II's own test of a point on a face may
    // come out either way, and then the sort decides.
    constexpr double                                  margin = 1e-10;
    bool                                              inside = true;
    typename Triangulation<dim>::active_cell_iterator cell;
    Point<dim>                                        lower, upper;
    for (const auto &point : particle_handler)
      {
        if (cell.state() != IteratorState::valid ||
            point.get_surrounding_cell() != cell)
          {
            cell  = point.get_surrounding_cell();
            lower = cell->vertex(0);
            upper = cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1);
          }
        const Point<dim> &position = point.get_location();
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double s = (position[d] - lower[d]) / (upper[d] - lower[d]);
            // (Written so that a NaN counts as outside.)
            if (!(s > margin && s < 1. - margin))
              inside = false;
          }
        if (!inside)
          break;
      }
    return !Utilities::MPI::logical_or(!inside, communicator);
  }



  template <int dim>
  void
  MaterialPoints<dim>::sort_into_cells(const unsigned int load_step)
  {
    // Most steps of a dynamic run move every point within its cell:
    // deal.II's sort would find each in its place and then reorder the
    // points' data in memory, 5-7 % of an explicit step.
    if (all_inside_their_cells())
      return;
    const auto n_before = particle_handler.n_global_particles();
    particle_handler.sort_particles_into_subdomains_and_cells();
    if (particle_handler.n_global_particles() != n_before)
      throw CollectiveError("Material points were lost while sorting them "
                            "into cells in load step " +
                            std::to_string(load_step) + ".");
  }



  template bool
  MaterialPoints<2>::all_inside_their_cells() const;
  template bool
  MaterialPoints<3>::all_inside_their_cells() const;
  template void
  MaterialPoints<2>::sort_into_cells(const unsigned int);
  template void
  MaterialPoints<3>::sort_into_cells(const unsigned int);
} // namespace impm
