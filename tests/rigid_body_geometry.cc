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
// The cone in the meridian plane (2D, for an axisymmetric grid): its gap and
// normal equal the 3D cone's in the plane y = 0 at 1,488 points off the axis
// (r, z), and those of the cone turned over (tip (0, 2), axis (0, -1)) at
// (r, 2 - z) with the normal's y turned over (to 1e-14); their normal's
// derivative against central differences; points 1 and 2 by hand as above.
// STL surfaces (3D): the unit cube [0, 1]^3 as an ASCII STL file of 12
// triangles (some listed clockwise from outside, all consistently), and the
// octahedron |x| + |y| + |z| <= 1 as a binary STL file of 8 triangles:
// 9. cube (0.5, 0.5, 0.9): inside under the top: gap -0.1, normal (0, 0, 1);
// 10. cube (1.2, 0.5, 0.5): gap 0.2, normal (1, 0, 0);
// 11. cube (1.3, 1.4, 0.5): nearest the edge x = y = 1 at (1, 1, 0.5):
//     gap 0.5, normal (0.6, 0.8, 0);
// 12. cube (1.1, 1.2, 1.2): nearest the corner (1, 1, 1): gap 0.3, normal
//     (1/3, 2/3, 2/3);
// 13. cube (0.9, 0.95, 0.5): inside, the side y = 1 nearest: gap -0.05,
//     normal (0, 1, 0);
// 14. octahedron (0.2, 0.2, 0.2): inside, below the face x + y + z = 1:
//     gap -(1 - 0.6) / sqrt 3 = -0.230940, normal (1, 1, 1) / sqrt 3;
// 15. octahedron (0, 0, 1.5): above the corner (0, 0, 1): gap 0.5, normal
//     (0, 0, 1);
// 16. octahedron (0.8, 0.8, 0): nearest the edge from (1, 0, 0) to
//     (0, 1, 0), at (0.5, 0.5, 0): gap sqrt 0.18 = 0.424264, normal
//     (0.707107, 0.707107, 0);
// and a cube with one triangle missing or one turned over is refused with
// a message naming the fault. The nearest triangle is found through a
// search tree (a bounding-volume hierarchy): on the unit cube cut into
// 1200 triangles the gap and normal at 343 points inside and outside (on
// no diagonal, so that the nearest side is unique) equal the box's exact
// ones: -min distance to a side inside, |x - clamp(x)| outside, the
// normal along it.
// The normal's derivative is compared with central differences (step
// 1e-6) at points on flat sides, on the turning of the cone (e_r) and at
// the profile's corners, for the cone above and a cone tilted along
// (1, 2, 2) / 3 with its tip at (0.3, -0.2, 0.1); the largest difference
// relative to the largest entry must be below 1e-6.

#include <deal.II/base/parameter_handler.h>

#include <impm/core/rigid_body.h>

#include <cstdint>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>

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
  /**
   * The cone in the meridian plane of an axisymmetric grid (2D, x the
   * radius) against @p cone (3D, tip (0, 0, 0), axis z, height 1, radius
   * 0.5, shaft 0.5): its proximity is the 3D cone's in the plane through
   * the axis, (r, z) -> (r, 0, z), and with the axis along -y (tip (0, 2))
   * the same mirrored, (r, 2 - z), the normal's y component turned over.
   */
  void
  check_meridian_cones(const RigidBody<3> &cone)
  {
    const auto meridian = make_body<2>({{"Shape", "cone"},
                                        {"Tip", "0, 0"},
                                        {"Axis", "0, 1"},
                                        {"Cone height", "1"},
                                        {"Cone radius", "0.5"},
                                        {"Shaft length", "0.5"}});
    const auto flipped  = make_body<2>({{"Shape", "cone"},
                                        {"Tip", "0, 2"},
                                        {"Axis", "0, -1"},
                                        {"Cone height", "1"},
                                        {"Cone radius", "0.5"},
                                        {"Shaft length", "0.5"}});
    std::cout << std::fixed;
    print("meridian cone 1", meridian, Point<2>(0.1, 0.6));
    print("meridian cone 2", meridian, Point<2>(0.6, 1.2));
    print("flipped meridian cone 1", flipped, Point<2>(0.1, 1.4));
    std::cout << std::defaultfloat;
    double                largest = 0.;
    unsigned int          n       = 0;
    std::vector<Point<2>> off_corners;
    // Off the axis, where the two sides of the profile tie inside (the
    // normal's direction is then either's).
    for (double r = 0.0375; r <= 0.9; r += 0.0375)
      for (double z = -0.4; z <= 1.9; z += 0.0375)
        {
          const auto in_3d = cone.proximity(Point<3>(r, 0., z), Point<3>());
          const auto in_2d = meridian.proximity(Point<2>(r, z), Point<2>());
          const auto mirrored =
            flipped.proximity(Point<2>(r, 2. - z), Point<2>());
          for (const double difference : {in_2d.gap - in_3d.gap,
                                          in_2d.normal[0] - in_3d.normal[0],
                                          in_2d.normal[1] - in_3d.normal[2],
                                          mirrored.gap - in_3d.gap,
                                          mirrored.normal[0] - in_3d.normal[0],
                                          mirrored.normal[1] + in_3d.normal[2]})
            largest = std::max(largest, std::abs(difference));
          ++n;
          off_corners.push_back(Point<2>(r + 0.0011, z + 0.0013));
        }
    std::cout << "meridian cones against the 3D cone at " << n
              << " points of the plane" << std::endl;
    impm_tests::check_below("meridian cones: largest difference of the gap "
                            "and the normal",
                            largest,
                            1e-14);
    impm_tests::check_below("meridian cone: normal derivative against "
                            "central differences",
                            derivative_difference(meridian, off_corners),
                            1e-6);
    std::vector<Point<2>> flipped_points;
    for (const auto &x : off_corners)
      flipped_points.push_back(Point<2>(x[0], 2. - x[1]));
    impm_tests::check_below("flipped meridian cone: the same",
                            derivative_difference(flipped, flipped_points),
                            1e-6);
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

  check_meridian_cones(cone);

  // STL surfaces.
  {
    const std::vector<Point<3>> corners = {Point<3>(0, 0, 0),
                                           Point<3>(1, 0, 0),
                                           Point<3>(1, 1, 0),
                                           Point<3>(0, 1, 0),
                                           Point<3>(0, 0, 1),
                                           Point<3>(1, 0, 1),
                                           Point<3>(1, 1, 1),
                                           Point<3>(0, 1, 1)};
    // Inward (clockwise from outside): the reader turns them over.
    const std::vector<std::array<unsigned int, 3>> cube = {{{0, 1, 2}},
                                                           {{0, 2, 3}},
                                                           {{4, 6, 5}},
                                                           {{4, 7, 6}},
                                                           {{0, 5, 1}},
                                                           {{0, 4, 5}},
                                                           {{3, 2, 6}},
                                                           {{3, 6, 7}},
                                                           {{0, 3, 7}},
                                                           {{0, 7, 4}},
                                                           {{1, 5, 6}},
                                                           {{1, 6, 2}}};
    {
      std::ofstream out("cube.stl");
      out << std::setprecision(17) << "solid cube\n";
      for (const auto &triangle : cube)
        {
          out << " facet normal 0 0 0\n  outer loop\n";
          for (const unsigned int v : triangle)
            out << "   vertex " << corners[v] << "\n";
          out << "  endloop\n endfacet\n";
        }
      out << "endsolid cube\n";
    }
    {
      // Binary: header, count, then normal and three corners (floats) and
      // two attribute bytes per triangle.
      std::ofstream     out("octahedron.stl", std::ios::binary);
      const std::string header(80, ' ');
      out.write(header.data(), 80);
      const std::uint32_t n = 8;
      out.write(reinterpret_cast<const char *>(&n), 4);
      for (const double sx : {-1., 1.})
        for (const double sy : {-1., 1.})
          for (const double sz : {-1., 1.})
            {
              // Counter-clockwise from outside when sx sy sz > 0.
              float       values[12] = {0, 0, 0};
              const bool  even       = sx * sy * sz > 0.;
              const float a[3] = {float(sx), 0, 0}, b[3] = {0, float(sy), 0},
                          c[3]      = {0, 0, float(sz)};
              const float *order[3] = {a, even ? b : c, even ? c : b};
              for (unsigned int k = 0; k < 3; ++k)
                for (unsigned int d = 0; d < 3; ++d)
                  values[3 + 3 * k + d] = order[k][d];
              out.write(reinterpret_cast<const char *>(values), 48);
              const std::uint16_t attribute = 0;
              out.write(reinterpret_cast<const char *>(&attribute), 2);
            }
    }
    std::cout << std::fixed;
    const auto box = make_body<3>({{"Shape", "stl"},
                                   {"STL file", "cube.stl"},
                                   {"Displacement", "0, 0, 0"}});
    print("cube 9", box, Point<3>(0.5, 0.5, 0.9));
    print("cube 10", box, Point<3>(1.2, 0.5, 0.5));
    print("cube 11", box, Point<3>(1.3, 1.4, 0.5));
    print("cube 12", box, Point<3>(1.1, 1.2, 1.2));
    print("cube 13", box, Point<3>(0.9, 0.95, 0.5));
    const auto octahedron = make_body<3>({{"Shape", "stl"},
                                          {"STL file", "octahedron.stl"},
                                          {"Displacement", "0, 0, 0"}});
    print("octahedron 14", octahedron, Point<3>(0.2, 0.2, 0.2));
    print("octahedron 15", octahedron, Point<3>(0, 0, 1.5));
    print("octahedron 16", octahedron, Point<3>(0.8, 0.8, 0));
    std::cout << std::defaultfloat;
    impm_tests::check_below(
      "STL cube and octahedron: normal derivative against central "
      "differences",
      std::max(derivative_difference(box,
                                     {Point<3>(1.3, 1.4, 0.5),
                                      Point<3>(1.1, 1.2, 1.2),
                                      Point<3>(0.5, 0.5, 0.9),
                                      Point<3>(-0.2, 0.3, -0.1)}),
               derivative_difference(octahedron,
                                     {Point<3>(0, 0.01, 1.5),
                                      Point<3>(0.8, 0.8, 0.01),
                                      Point<3>(0.3, 0.2, 0.1)})),
      1e-6);
    for (const unsigned int fault : {0, 1})
      {
        auto faulty = cube;
        if (fault == 0)
          faulty.pop_back();
        else
          std::swap(faulty[3][1], faulty[3][2]);
        try
          {
            TriangulatedSurface surface(corners, faulty);
            std::cout << "a faulty cube was accepted" << std::endl;
          }
        catch (const std::runtime_error &error)
          {
            std::cout << "refused: " << error.what() << std::endl;
          }
      }

    // The search tree on a finer mesh: the unit cube with every side cut
    // into 10 x 10 squares (1200 triangles), at 7^3 points inside and
    // outside, against the box's exact signed distance and normal.
    const unsigned int n = 10;
    // The vertices on the grid of 1/n, each once.
    std::map<std::array<unsigned int, 3>, unsigned int> vertex_index;
    std::vector<Point<3>>                               fine_vertices;
    const auto vertex_at = [&](const std::array<unsigned int, 3> &grid) {
      const auto found = vertex_index.find(grid);
      if (found != vertex_index.end())
        return found->second;
      fine_vertices.emplace_back(double(grid[0]) / n,
                                 double(grid[1]) / n,
                                 double(grid[2]) / n);
      const unsigned int index = fine_vertices.size() - 1;
      vertex_index[grid]       = index;
      return index;
    };
    std::vector<std::array<unsigned int, 3>> fine_triangles;
    for (unsigned int axis = 0; axis < 3; ++axis)
      for (const unsigned int side : {0u, n})
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
              const std::array<std::pair<unsigned int, unsigned int>, 4>
                corners = {{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
              std::array<unsigned int, 4> square;
              for (unsigned int k = 0; k < 4; ++k)
                {
                  std::array<unsigned int, 3> grid;
                  grid[axis] = side;
                  grid[a]    = corners[k].first;
                  grid[b]    = corners[k].second;
                  square[k]  = vertex_at(grid);
                }
              // (a, b, axis) is right-handed: counter-clockwise from
              // outside on the upper side, clockwise on the lower one.
              if (side == n)
                {
                  fine_triangles.push_back({{square[0], square[1], square[2]}});
                  fine_triangles.push_back({{square[0], square[2], square[3]}});
                }
              else
                {
                  fine_triangles.push_back({{square[0], square[2], square[1]}});
                  fine_triangles.push_back({{square[0], square[3], square[2]}});
                }
            }
    const TriangulatedSurface fine(fine_vertices, fine_triangles);
    const std::vector<double> coordinates = {
      -0.31, 0.07, 0.23, 0.41, 0.66, 0.88, 1.19};
    double largest_gap_error = 0., largest_normal_error = 0.;
    for (const double x : coordinates)
      for (const double y : coordinates)
        for (const double z : coordinates)
          {
            const Point<3> at(x, y, z);
            Point<3>       nearest;
            bool           inside = true;
            for (unsigned int d = 0; d < 3; ++d)
              {
                nearest[d] = std::clamp(at[d], 0., 1.);
                inside     = inside && nearest[d] == at[d];
              }
            double       exact_gap = at.distance(nearest);
            Tensor<1, 3> exact_normal;
            if (inside)
              {
                exact_gap = -1.;
                for (unsigned int d = 0; d < 3; ++d)
                  for (const double side : {0., 1.})
                    if (std::abs(at[d] - side) < -exact_gap)
                      {
                        exact_gap       = -std::abs(at[d] - side);
                        exact_normal    = Tensor<1, 3>();
                        exact_normal[d] = side == 1. ? 1. : -1.;
                      }
              }
            else
              exact_normal = (at - nearest) / exact_gap;
            const auto proximity = fine.proximity(at);
            largest_gap_error =
              std::max(largest_gap_error, std::abs(proximity.gap - exact_gap));
            largest_normal_error =
              std::max(largest_normal_error,
                       (proximity.normal - exact_normal).norm());
          }
    std::cout << "fine cube: " << fine.get_triangles().size() << " triangles"
              << std::endl;
    impm_tests::check_below(
      "fine cube through the search tree: largest gap and normal error at "
      "343 points",
      std::max(largest_gap_error, largest_normal_error),
      1e-12);
  }

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
