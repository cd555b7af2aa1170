// The geometry of rigid bodies that the contact needs: the signed distance
// of a point from the surface, the outward normal and the normal's
// derivative, for the cone on a shaft (3D, issue 13) and the polygon (2D),
// against hand calculations; the normal's derivative against central
// differences of the normal; the cone's bounding box and surface.
//
// Cone: tip (0, 0, 0), axis (0, 0, 1), height 1, radius 0.5, shaft 0.5
// (top at z = 1.5). In the plane through the axis, (r, z), the slant side
// runs from (0, 0) to (0.5, 1) with outward normal (2, -1) / sqrt 5 =
// (0.894427, -0.447214), so the distance of (r, z) from it is
// (2 r - z) / sqrt 5:
// 1. (0.1, 0, 0.6): inside, slant nearest: (0.2 - 0.6) / sqrt 5 =
//    -0.178885 (the shaft side is 0.4 away, the top 0.9); normal
//    (0.894427, 0, -0.447214);
// 2. (0.6, 0, 1.2): beside the shaft: gap 0.1, normal (1, 0, 0);
// 3. (0, 0.3, 1.7): above the top: gap 0.2, normal (0, 0, 1);
// 4. (0, 0, -0.2): below the tip: gap 0.2, normal (0, 0, -1);
// 5. (0.3, 0.4, -0.1): r = 0.5, z = -0.1, the foot of the slant at
//    parameter (0.5 0.5 - 0.1) / 1.25 = 0.12 (inside the side): gap
//    (1 + 0.1) / sqrt 5 = 0.491935; normal 0.894427 e_r - 0.447214 e_z,
//    e_r = (0.6, 0.8, 0): (0.536656, 0.715542, -0.447214);
// 6. (0.45, 0, 1.4): inside the shaft, its side 0.05 away (the top 0.1):
//    gap -0.05, normal (1, 0, 0);
// the cone moved by (1, 0, 0) puts (1.1, 0, 0.6) where point 1 was:
// gap -0.178885.
// Tilted cone (below): its bounding box, by hand: the base's centre
// tip + 0.8 a = (0.566667, 0.333333, 0.633333) and the top's tip + 1.4 a
// = (0.766667, 0.733333, 1.033333), a circle of radius 0.3 reaching
// 0.3 sqrt(1 - a_d^2) = 0.282843 in x and 0.223607 in y and z:
// [0.283824, -0.2, 0.1] - [1.049509, 0.956940, 1.256940].
// Polygon (2D): the triangle (0, 0), (2, 0), (0, 1), listed clockwise as
// (0, 0), (0, 1), (2, 0) to check the orientation:
// 7. (0.5, 0.2): inside, nearest the bottom (0.2; the left side 0.5, the
//    slant (1 - 0.5/2 - 0.2) 2 / sqrt 5 = 0.491935): gap -0.2, normal
//    (0, -1);
// 8. (-0.3, -0.4): outside below the corner (0, 0): gap 0.5, normal
//    (-0.6, -0.8), derivative (I - n n) / 0.5.
// The normal's derivative is compared with central differences (step
// 1e-6) at points on flat sides, on the turning of the cone (e_r) and at
// the profile's corners, for the cone above and a cone tilted along
// (1, 2, 2) / 3 with its tip at (0.3, -0.2, 0.1); the largest difference
// relative to the largest entry must be below 1e-6.

#include <deal.II/base/parameter_handler.h>

#include <impm/contact/rigid_body.h>

#include <iomanip>
#include <iostream>

#include "tests.h"

using namespace impm;

namespace
{
  template <int dim>
  RigidBody<dim>
  make_body(const std::vector<std::pair<std::string, std::string>> &entries)
  {
    ParameterHandler prm;
    RigidBody<dim>::declare_parameters(prm);
    prm.enter_subsection("Rigid body 1");
    for (const auto &[name, value] : entries)
      prm.set(name, value);
    prm.leave_subsection();
    RigidBody<dim> body;
    body.parse_parameters(prm, 1);
    return body;
  }

  template <int dim>
  void
  print(const std::string &what, const RigidBody<dim> &body, Point<dim> x)
  {
    const auto proximity = body.proximity(x, Tensor<1, dim>());
    std::cout << what << ": gap " << proximity.gap << ", normal ("
              << proximity.normal << ")" << std::endl;
  }

  /** The largest difference between the normal's derivative and central
   *  differences of the normal at @p points, relative to its largest
   *  entry. */
  template <int dim>
  double
  derivative_difference(const RigidBody<dim>          &body,
                        const std::vector<Point<dim>> &points)
  {
    double       largest_entry = 0., largest_difference = 0.;
    const double step = 1e-6;
    for (const auto &x : points)
      {
        const auto derivative = body.proximity(x, Tensor<1, dim>());
        for (unsigned int j = 0; j < dim; ++j)
          {
            Point<dim> plus = x, minus = x;
            plus[j] += step;
            minus[j] -= step;
            const Tensor<1, dim> difference =
              (body.proximity(plus, Tensor<1, dim>()).normal -
               body.proximity(minus, Tensor<1, dim>()).normal) /
              (2. * step);
            for (unsigned int i = 0; i < dim; ++i)
              {
                largest_entry =
                  std::max(largest_entry,
                           std::abs(derivative.normal_derivative[i][j]));
                largest_difference =
                  std::max(largest_difference,
                           std::abs(derivative.normal_derivative[i][j] -
                                    difference[i]));
              }
          }
      }
    return largest_difference / largest_entry;
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6) << std::fixed;
  const auto cone = make_body<3>({{"Shape", "cone"},
                                  {"Tip", "0, 0, 0"},
                                  {"Axis", "0, 0, 2"},
                                  {"Cone height", "1"},
                                  {"Cone radius", "0.5"},
                                  {"Shaft length", "0.5"},
                                  {"Displacement", "0, 0, 0"}});
  print("cone 1", cone, Point<3>(0.1, 0, 0.6));
  print("cone 2", cone, Point<3>(0.6, 0, 1.2));
  print("cone 3", cone, Point<3>(0, 0.3, 1.7));
  print("cone 4", cone, Point<3>(0, 0, -0.2));
  print("cone 5", cone, Point<3>(0.3, 0.4, -0.1));
  print("cone 6", cone, Point<3>(0.45, 0, 1.4));
  const auto moved = cone.proximity(Point<3>(1.1, 0, 0.6), Point<3>(1, 0, 0));
  std::cout << "cone 1 moved by (1, 0, 0): gap " << moved.gap << std::endl;

  const auto triangle =
    make_body<2>({{"Shape", "polygon"}, {"Vertices", "0, 0; 0, 1; 2, 0"}});
  print("polygon 7", triangle, Point<2>(0.5, 0.2));
  print("polygon 8", triangle, Point<2>(-0.3, -0.4));
  const auto corner = triangle.proximity(Point<2>(-0.3, -0.4), Tensor<1, 2>());
  std::cout << "polygon 8 derivative times 0.5: ("
            << 0.5 * corner.normal_derivative << ") (I - n n: 0.64 -0.48 "
            << "-0.48 0.36)" << std::endl;

  const auto            tilted = make_body<3>({{"Shape", "cone"},
                                               {"Tip", "0.3, -0.2, 0.1"},
                                               {"Axis", "1, 2, 2"},
                                               {"Cone height", "0.8"},
                                               {"Cone radius", "0.3"},
                                               {"Shaft length", "0.6"},
                                               {"Displacement", "0, 0, 0"}});
  std::vector<Point<3>> points = {Point<3>(0.1, 0.02, 0.6),
                                  Point<3>(0.6, 0.1, 1.2),
                                  Point<3>(0.05, 0.3, 1.7),
                                  Point<3>(0.01, 0.02, -0.2),
                                  Point<3>(0.3, 0.4, -0.1),
                                  Point<3>(0.7, 0.1, 1.6)};
  std::cout << std::defaultfloat;
  impm_tests::check_below("cone: normal derivative against central "
                          "differences, largest relative difference",
                          derivative_difference(cone, points),
                          1e-6);
  std::vector<Point<3>> tilted_points;
  for (const auto &x : points)
    tilted_points.push_back(Point<3>(0.3, -0.2, 0.1) + 0.6 * x);
  impm_tests::check_below("tilted cone: the same",
                          derivative_difference(tilted, tilted_points),
                          1e-6);
  impm_tests::check_below("polygon: the same",
                          derivative_difference(triangle,
                                                {Point<2>(0.5, 0.2),
                                                 Point<2>(-0.3, -0.4),
                                                 Point<2>(2.3, -0.1),
                                                 Point<2>(1.2, 0.8)}),
                          1e-6);

  // The tilted cone's box holds its surface's vertices and touches it.
  const auto box     = tilted.bounding_box(Tensor<1, 3>());
  const auto surface = tilted.surface(Tensor<1, 3>());
  Point<3>   lower = surface.vertices[0], upper = surface.vertices[0];
  for (const auto &vertex : surface.vertices)
    for (unsigned int d = 0; d < 3; ++d)
      {
        lower[d] = std::min(lower[d], vertex[d]);
        upper[d] = std::max(upper[d], vertex[d]);
      }
  std::cout << std::fixed << "tilted cone: bounding box [" << box.first
            << "] - [" << box.second << "]" << std::endl
            << "its surface (" << surface.vertices.size() << " vertices, "
            << surface.faces.size() << " faces) spans [" << lower << "] - ["
            << upper << "]" << std::endl;
  double largest_gap = 0.;
  for (const auto &vertex : surface.vertices)
    largest_gap =
      std::max(largest_gap,
               std::abs(tilted.proximity(vertex, Tensor<1, 3>()).gap));
  std::cout << std::defaultfloat;
  impm_tests::check_below("the surface's vertices' largest |gap|",
                          largest_gap,
                          1e-12);
}
