// The Traction effect's total force against the traction times the length
// of the loaded side, for a box, a disc and a polygon in 2D, and the face
// weights that spread each share over the grid (they must sum to one).
//
// Grid [0, 4] x [0, 4], 8 x 8 cells, 2 x 2 points per cell (spacing
// 0.25 m): the points are the lattice sites inside each body, as the
// seeding places them. Traction t = (300, -1e4) Pa at load factor 1.
// Exact lengths of the loaded sides:
// 1. box [0.5, 2.5] x [0.5, 3], side y+: L = 2;
// 2. disc centre (2.03, 1.97), radius 1.3, side y+ (the upper half circle):
//    L = pi 1.3 = 4.08407045; side x- (the left half): the same;
// 3. polygon (0.1, 0.2), (3.3, 0.4), (2.6, 2.9), (0.7, 2.2) (counter-
//    clockwise), side y+: the edges whose outward normal (e_y, -e_x) has a
//    positive y component, i.e. those with e_x < 0:
//    |(-0.7, 2.5)| = sqrt(6.74) = 2.59615100, |(-1.9, -0.7)| = sqrt(4.10) =
//    2.02484567, |(-0.6, -2.0)| = sqrt(4.36) = 2.08806130; L = 6.70905797.
// Before the loads were cut along the true boundary, the disc's side y+
// carried the staircase of its lattice faces (its points' count times
// 0.25 m), not pi R.

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
  void
  check(const std::string &name,
        const Body<2>     &body,
        const std::string &boundary,
        const double       exact_length)
  {
    CartesianGrid<2> grid;
    grid.initialize(Point<2>(0., 0.), Point<2>(4., 4.), {{8, 8}});

    // The lattice sites inside the body.
    std::vector<MaterialPointInfo<2>> points;
    for (unsigned int i = 0; i < 16; ++i)
      for (unsigned int j = 0; j < 16; ++j)
        {
          const Point<2> x((i + 0.5) * 0.25, (j + 0.5) * 0.25);
          if (body.contains(x))
            points.push_back({16ull * i + j, x, 0, 1.});
        }

    ParameterHandler prm;
    const auto      &entry = ForceEffectList<2>::find("Traction");
    prm.enter_subsection("Traction");
    entry.declare_parameters(prm);
    prm.set("Boundary", boundary);
    prm.set("Traction", "300, -1e4");
    auto traction = entry.create(prm);
    prm.leave_subsection();
    traction->initialize(points, {body}, grid, MPI_COMM_SELF);

    std::vector<FaceForce<2>> faces;
    traction->add_face_forces(points, 1., faces);
    Tensor<1, 2>            total;
    double                  worst_sum = 0.;
    const BasisEvaluator<2> evaluator(grid, BasisType::gimp);
    for (const auto &face : faces)
      {
        total += face.force;
        // The face weights of the point's support sum to one.
        PointSupport<2>                                support;
        std::array<double, PointSupport<2>::max_nodes> weights;
        const Tensor<1, 2> half_length({0.125, 0.125});
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
    const Tensor<1, 2> expected({300. * exact_length, -1e4 * exact_length});
    std::cout << name << ", side " << boundary << ": " << faces.size()
              << " loaded points" << std::endl;
    impm_tests::check_below("  |total force - t L| / |t L|",
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

  Body<2> disc = box;
  disc.shape   = Body<2>::Shape::disc;
  disc.center  = Point<2>(2.03, 1.97);
  disc.radius  = 1.3;
  check("disc", disc, "y+", M_PI * 1.3);
  check("disc", disc, "x-", M_PI * 1.3);

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
}
