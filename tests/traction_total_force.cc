// The Traction effect's total force against the traction times the length
// or area of the loaded boundary, for a box, a disc and a polygon in 2D and
// a sphere, a cylinder and a box in 3D, by side and by region alone, and the
// face weights that spread each share over the grid (they must sum to one).
//
// Grid [0, 4]^d, 8 cells per direction, 2 points per cell and direction
// (spacing 0.25 m): the points are the lattice sites inside each body, as
// the seeding places them. Traction t = (300, -1e4) Pa (3D: (300, 200,
// -1e4)) at load factor 1. Exact lengths and areas of the loaded parts:
// 1. box [0.5, 2.5] x [0.5, 3], side y+: L = 2; by the region [0, 4]^2
//    (the whole boundary): the perimeter 9;
// 2. disc centre (2.03, 1.97), radius 1.3, side y+ (the upper half circle):
//    L = pi 1.3 = 4.08407045; side x- (the left half): the same; by a
//    region holding it all: 2 pi 1.3 = 8.16814090;
// 3. polygon (0.1, 0.2), (3.3, 0.4), (2.6, 2.9), (0.7, 2.2) (counter-
//    clockwise), side y+: the edges whose outward normal (e_y, -e_x) has a
//    positive y component, i.e. those with e_x < 0:
//    |(-0.7, 2.5)| = sqrt(6.74) = 2.59615100, |(-1.9, -0.7)| = sqrt(4.10) =
//    2.02484567, |(-0.6, -2.0)| = sqrt(4.36) = 2.08806130; L = 6.70905797;
// 4. a square turned by 45 degrees, vertices (2, 0.5), (3.5, 2), (2, 3.5),
//    (0.5, 2): its upper right side alone, by the region [2.05, 4]^2 (the
//    side's pieces, cut at the lattice lines x = 0.25 m, have midpoints
//    with x and y in [2.125, 3.375]; the neighbouring sides' have x < 2 or
//    y < 2): L = 1.5 sqrt 2 = 2.12132034; the whole boundary: 6 sqrt 2;
// 5. sphere centre (2.02, 1.97, 2.04), radius 1.3, side z+ (the upper half):
//    A = 2 pi 1.3^2 = 10.61858317 (Archimedes' zones); the whole sphere by
//    a region: 4 pi 1.3^2 = 21.23716634;
// 6. box [0.5, 2.5] x [0.5, 3] x [1, 2.5] by the region [0, 4]^3: the whole
//    surface 2 (2 x 2.5 + 2 x 1.5 + 2.5 x 1.5) = 23.5 (lattice faces); by
//    the region [0.6, 4]^3 the faces whose centres are in it, all but x-
//    and y-: 23.5 - 2.5 x 1.5 - 2 x 1.5 = 16.75 (until 2026-11-29 a box in
//    3D took every open face of the points in the region: 23.5); the box
//    [-1, 2.5] x [0.5, 3] x [1, 2.5] across x = 0 by the region [0, 4]^3:
//    its surface in x > 0 without the cut, 2.5 x 1.5 + 2 (2.5 x 1.5) +
//    2 (2.5 x 2.5) = 23.75 (it took the cut's 3.75 too).
// 8. bodies across the grid's faces (symmetry planes; the part outside is
//    cut off and carries nothing): the box [-1, 2.5] x [0.5, 3], side y+:
//    2.5 (it carried 3.5 on the points next to x = 0); the disc centred
//    on x = 0, side y+: pi 1.3 / 2; the sphere centred at (0, 0, 2.04),
//    side z+: 2 pi 1.3^2 / 4 (the sectors come in multiples of four).
// 9. cylinder, base centre (2.02, 1.97, 0.6), radius 1.3, height 2.5: side
//    z+ (the top disc, each lattice cell's exact part): pi 1.3^2; side x-
//    (half of its side): pi 1.3 x 2.5; the whole surface by a region:
//    2 pi 1.3^2 + 2 pi 1.3 x 2.5; centred on the axis x = y = 0 (a quarter
//    model): z- pi 1.3^2 / 4, y+ (the half facing +y, of which the part in
//    x > 0) pi 1.3 x 2.5 / 2; centred at (0.3, 0.2), its top in x, y > 0:
//    with u = x - 0.3, s = sqrt(1.3^2 - u^2), k = sqrt(1.3^2 - 0.2^2), the
//    integral of 0.2 + s over -0.3 < u < k and of 2 s over k < u < 1.3,
//    2.03280385289 (Simpson's rule on 2 million intervals: 2.0328038527).
//    Before, a cylinder's ends and side carried their lattice faces (the
//    quarter model's top 0.96 % too large), and a body's parts beyond the
//    grid loaded the points next to the plane.
// 7. Cook's membrane scaled by 1/16, (0, 0), (3, 2.75), (3, 3.75), (0, 2.75),
//    side x+: the edges whose outward normal has a positive x component,
//    the right edge (length 1) and the lower, slanted edge (normal
//    (2.75, -3)/sqrt(16.5625), length sqrt(16.5625) = 4.06970...). Clipped
//    by the region in every direction: from y = 43/16 (the scene's y = 43)
//    the right edge and the slanted edge's part above y = 43/16,
//    L = 1 + 0.0625 sqrt(16.5625)/2.75 = 1.09249 (the side's 1 and 9.25 %
//    more: the slanted edge's part above y = 43/16); side y- (the slanted
//    edge alone) in the region 0.6 <= x <= 1.3, y <= 1, clipped in x at
//    0.6 and in y at 1 (x = 12/11): (12/11 - 0.6) sqrt(16.5625)/3 =
//    0.66586; between y = 3.1 and 3.45 (cuts off the lattice lines) the
//    right edge's 0.35; side y- left of x = 1.3: 1.3 sqrt(16.5625)/3.
//    Before the region clipped the pieces (cut at the lattice lines) a
//    piece was in or out by its midpoint: 1, 0.5 sqrt(16.5625)/3, 0.5 and
//    1.25 sqrt(16.5625)/3.
//    A region must also hold the boundary points that carry the load (the
//    lattice sites next to the side): x+ with a region from x = 2.95 holds
//    none (they lie at x = 2.875) and is refused.
// Before the loads were cut along the true boundary, the disc's side y+
// carried the staircase of its lattice faces (its points' count times
// 0.25 m), not pi R; before zones, the sphere's its lattice faces.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <impm/basis/basis_functions.h>
#include <impm/core/effects.h>

#include <cmath>
#include <iostream>

#include "tests.h"

using namespace impm;

namespace
{
  template <int dim>
  void
  check(const std::string         &name,
        const Body<dim>           &body,
        const std::string         &boundary,
        const double               exact_size,
        const std::vector<double> &region = {})
  {
    CartesianGrid<dim> grid;
    Point<dim>         upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 4.;
    std::array<unsigned int, dim> cells;
    cells.fill(8);
    grid.initialize(Point<dim>(), upper, cells);

    // The lattice sites inside the body.
    std::vector<MaterialPointInfo<dim>> points;
    const unsigned int                  n = dim == 2 ? 16 * 16 : 16 * 16 * 16;
    for (unsigned int k = 0; k < n; ++k)
      {
        Point<dim>   x;
        unsigned int rest = k;
        for (unsigned int d = 0; d < dim; ++d, rest /= 16)
          x[d] = (rest % 16 + 0.5) * 0.25;
        if (body.contains(x))
          points.push_back({k, x, 0, 1.});
      }

    ParameterHandler prm;
    const auto      &entry = ForceEffectList<dim>::find("Traction");
    prm.enter_subsection("Traction");
    entry.declare_parameters(prm);
    prm.set("Boundary", boundary);
    prm.set("Traction", dim == 2 ? "300, -1e4" : "300, 200, -1e4");
    if (!region.empty())
      {
        std::string lower, upper_corner;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower += (d > 0 ? ", " : "") + std::to_string(region[d]);
            upper_corner +=
              (d > 0 ? ", " : "") + std::to_string(region[dim + d]);
          }
        prm.set("Region lower corner", lower);
        prm.set("Region upper corner", upper_corner);
      }
    auto traction = entry.create(prm);
    prm.leave_subsection();
    traction->initialize(points, {body}, grid, MPI_COMM_SELF);

    std::vector<FaceForce<dim>> faces;
    traction->add_face_forces(points, 1., faces);
    Tensor<1, dim>            total;
    double                    worst_sum = 0.;
    const BasisEvaluator<dim> evaluator(grid, BasisType::gimp);
    Tensor<1, dim>            half_length;
    for (unsigned int d = 0; d < dim; ++d)
      half_length[d] = 0.125;
    for (const auto &face : faces)
      {
        total += face.force;
        // The face weights of the point's support sum to one.
        PointSupport<dim>                                support;
        std::array<double, PointSupport<dim>::max_nodes> weights;
        evaluator.evaluate(points[face.point].initial_position,
                           half_length,
                           support);
        evaluator.face_weights(points[face.point].initial_position,
                               half_length,
                               face.axis,
                               face.sign,
                               support,
                               weights);
        double sum = 0.;
        for (unsigned int v = 0; v < support.n_nodes; ++v)
          sum += weights[v];
        worst_sum = std::max(worst_sum, std::abs(sum - 1.));
      }
    Tensor<1, dim> t;
    t[0]       = 300.;
    t[dim - 1] = -1e4;
    if (dim == 3)
      t[1] = 200.;
    const Tensor<1, dim> expected = exact_size * t;
    std::cout << name << " (" << dim << "D), "
              << (boundary == "region" ? "the boundary in the region" :
                                         "side " + boundary)
              << ": " << faces.size() << " loaded faces" << std::endl;
    impm_tests::check_below(std::string("  |total force - t ") +
                              (dim == 2 ? "L| / |t L|" : "A| / |t A|"),
                            (total - expected).norm() / expected.norm(),
                            1e-10);
    impm_tests::check_below("  largest |sum of face weights - 1|",
                            worst_sum,
                            1e-14);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  Body<2> box;
  box.name                 = "Body 1";
  box.shape                = Body<2>::Shape::box;
  box.lower_corner         = Point<2>(0.5, 0.5);
  box.upper_corner         = Point<2>(2.5, 3.);
  box.points_per_direction = 2;
  check("box", box, "y+", 2.);
  check("box", box, "region", 9., {0., 0., 4., 4.});

  Body<2> disc = box;
  disc.shape   = Body<2>::Shape::disc;
  disc.center  = Point<2>(2.03, 1.97);
  disc.radius  = 1.3;
  check("disc", disc, "y+", M_PI * 1.3);
  check("disc", disc, "x-", M_PI * 1.3);
  check("disc", disc, "region", 2. * M_PI * 1.3, {0., 0., 4., 4.});

  Body<2> polygon  = box;
  polygon.shape    = Body<2>::Shape::polygon;
  polygon.vertices = {Point<2>(0.1, 0.2),
                      Point<2>(3.3, 0.4),
                      Point<2>(2.6, 2.9),
                      Point<2>(0.7, 2.2)};
  check("polygon",
        polygon,
        "y+",
        std::sqrt(6.74) + std::sqrt(4.10) + std::sqrt(4.36));

  Body<2> diamond  = polygon;
  diamond.vertices = {Point<2>(2., 0.5),
                      Point<2>(3.5, 2.),
                      Point<2>(2., 3.5),
                      Point<2>(0.5, 2.)};
  check("turned square, upper right side",
        diamond,
        "region",
        1.5 * std::sqrt(2.),
        {2.05, 2.05, 4., 4.});
  check(
    "turned square", diamond, "region", 6. * std::sqrt(2.), {0., 0., 4., 4.});

  // Cook's membrane at 1/16 scale (case 7 above), side x+ clipped by
  // regions.
  Body<2> cook         = polygon;
  cook.vertices        = {Point<2>(0., 0.),
                          Point<2>(3., 2.75),
                          Point<2>(3., 3.75),
                          Point<2>(0., 2.75)};
  const double slanted = std::sqrt(16.5625); // the lower edge's length
  check("Cook's membrane, region from y = 43/16",
        cook,
        "x+",
        1. + 0.0625 * slanted / 2.75,
        {0., 43. / 16., 4., 4.});
  check("Cook's membrane, y- side in the region 0.6 <= x <= 1.3, y <= 1",
        cook,
        "y-",
        (12. / 11. - 0.6) * slanted / 3.,
        {0.6, 0., 1.3, 1.});
  check("Cook's membrane, region 3.1 <= y <= 3.45",
        cook,
        "x+",
        0.35,
        {0., 3.1, 4., 3.45});
  check("Cook's membrane, y- side in the region x <= 1.3",
        cook,
        "y-",
        1.3 * slanted / 3.,
        {-1., -1., 1.3, 4.});

  Body<3> sphere;
  sphere.name                 = "Body 1";
  sphere.shape                = Body<3>::Shape::sphere;
  sphere.center               = Point<3>(2.02, 1.97, 2.04);
  sphere.radius               = 1.3;
  sphere.points_per_direction = 2;
  check("sphere", sphere, "z+", 2. * M_PI * 1.3 * 1.3);
  check("sphere",
        sphere,
        "region",
        4. * M_PI * 1.3 * 1.3,
        {0., 0., 0., 4., 4., 4.});

  // A body across the grid's faces (a symmetry plane: the part beyond is
  // cut off) carries the load of its part inside only (case 8 above).
  Body<2> box_across      = box;
  box_across.lower_corner = Point<2>(-1., 0.5);
  check("box across x = 0", box_across, "y+", 2.5);
  Body<2> disc_across = disc;
  disc_across.center  = Point<2>(0., 1.97);
  check("disc across x = 0", disc_across, "y+", 0.5 * M_PI * 1.3);
  Body<3> sphere_across = sphere;
  sphere_across.center  = Point<3>(0., 0., 2.04);
  check("quarter sphere", sphere_across, "z+", 0.5 * M_PI * 1.3 * 1.3);

  // Case 9: the cylinder.
  Body<3> cylinder = sphere;
  cylinder.shape   = Body<3>::Shape::cylinder;
  cylinder.center  = Point<3>(2.02, 1.97, 0.6);
  cylinder.height  = 2.5;
  check("cylinder", cylinder, "z+", M_PI * 1.3 * 1.3);
  check("cylinder", cylinder, "x-", M_PI * 1.3 * 2.5);
  check("cylinder",
        cylinder,
        "region",
        2. * M_PI * 1.3 * 1.3 + 2. * M_PI * 1.3 * 2.5,
        {0., 0., 0., 4., 4., 4.});
  Body<3> cylinder_across = cylinder;
  cylinder_across.center  = Point<3>(0., 0., 0.6);
  check("quarter cylinder", cylinder_across, "z-", 0.25 * M_PI * 1.3 * 1.3);
  check("quarter cylinder", cylinder_across, "y+", 0.5 * M_PI * 1.3 * 2.5);
  cylinder_across.center = Point<3>(0.3, 0.2, 0.6);
  check("cylinder across x = 0 and y = 0, off its axis",
        cylinder_across,
        "z+",
        2.0328038528856567);

  Body<3> box_3d      = sphere;
  box_3d.shape        = Body<3>::Shape::box;
  box_3d.lower_corner = Point<3>(0.5, 0.5, 1.);
  box_3d.upper_corner = Point<3>(2.5, 3., 2.5);
  check("box", box_3d, "region", 23.5, {0., 0., 0., 4., 4., 4.});
  check("box, the region from 0.6",
        box_3d,
        "region",
        16.75,
        {0.6, 0.6, 0.6, 4., 4., 4.});
  Body<3> box_3d_across      = box_3d;
  box_3d_across.lower_corner = Point<3>(-1., 0.5, 1.);
  check("box across x = 0",
        box_3d_across,
        "region",
        23.75,
        {0., 0., 0., 4., 4., 4.});
}
