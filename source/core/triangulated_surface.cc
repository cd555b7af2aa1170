#include <deal.II/base/symmetric_tensor.h>

#include <impm/core/triangulated_surface.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace impm
{
  namespace
  {
    /** The nearest point of a triangle and which of its features it lies
     *  on. */
    struct NearestOnTriangle
    {
      Point<3> point;
      /** 0: inside the face; 1, 2, 3: corner 0, 1, 2; 4, 5, 6: edge from
       *  corner 0, 1, 2 to the next corner. */
      unsigned int feature;
    };

    /** The nearest point to @p p of the triangle @p a, @p b, @p c, by the
     *  regions of the triangle's plane (the corners' and edges' Voronoi
     *  regions, then the face). */
    NearestOnTriangle
    nearest_on_triangle(const Point<3> &p,
                        const Point<3> &a,
                        const Point<3> &b,
                        const Point<3> &c)
    {
      const Tensor<1, 3> ab = b - a, ac = c - a, ap = p - a;
      const double       d1 = ab * ap, d2 = ac * ap;
      if (d1 <= 0. && d2 <= 0.)
        return {a, 1};
      const Tensor<1, 3> bp = p - b;
      const double       d3 = ab * bp, d4 = ac * bp;
      if (d3 >= 0. && d4 <= d3)
        return {b, 2};
      const double vc = d1 * d4 - d3 * d2;
      if (vc <= 0. && d1 >= 0. && d3 <= 0.)
        return {a + d1 / (d1 - d3) * ab, 4};
      const Tensor<1, 3> cp = p - c;
      const double       d5 = ab * cp, d6 = ac * cp;
      if (d6 >= 0. && d5 <= d6)
        return {c, 3};
      const double vb = d5 * d2 - d1 * d6;
      if (vb <= 0. && d2 >= 0. && d6 <= 0.)
        return {a + d2 / (d2 - d6) * ac, 6};
      const double va = d3 * d6 - d5 * d4;
      if (va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.)
        return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b), 5};
      const double denominator = va + vb + vc;
      return {a + (vb / denominator) * ab + (vc / denominator) * ac, 0};
    }

    /** The triangles' corners as read from an STL file, ASCII or binary. */
    std::vector<Point<3>>
    read_stl_corners(const std::string &file_name)
    {
      std::ifstream file(file_name, std::ios::binary);
      if (!file)
        throw std::runtime_error("cannot open the file '" + file_name + "'");
      const std::string     bytes((std::istreambuf_iterator<char>(file)),
                              std::istreambuf_iterator<char>());
      std::vector<Point<3>> corners;
      // Binary: an 80-byte header, the number of triangles, 50 bytes each.
      if (bytes.size() >= 84)
        {
          std::uint32_t n = 0;
          std::memcpy(&n, bytes.data() + 80, 4);
          if (bytes.size() == 84 + 50 * static_cast<std::size_t>(n))
            {
              for (std::uint32_t t = 0; t < n; ++t)
                for (unsigned int k = 0; k < 3; ++k)
                  {
                    float xyz[3];
                    std::memcpy(xyz,
                                bytes.data() + 84 + 50 * t + 12 + 12 * k,
                                12);
                    corners.emplace_back(xyz[0], xyz[1], xyz[2]);
                  }
              return corners;
            }
        }
      // ASCII: every "vertex x y z".
      std::istringstream text(bytes);
      std::string        word;
      while (text >> word)
        if (word == "vertex")
          {
            double x, y, z;
            if (!(text >> x >> y >> z))
              throw std::runtime_error("'" + file_name +
                                       "' has a vertex without three numbers");
            corners.emplace_back(x, y, z);
          }
      if (corners.empty() || bytes.compare(0, 5, "solid") != 0)
        throw std::runtime_error("'" + file_name +
                                 "' is neither a binary nor an ASCII STL file "
                                 "with triangles");
      if (corners.size() % 3 != 0)
        throw std::runtime_error("'" + file_name +
                                 "' has a facet without three vertices");
      return corners;
    }
  } // namespace



  TriangulatedSurface::TriangulatedSurface(const std::string &file_name)
  {
    // One vertex per position.
    std::map<std::array<double, 3>, unsigned int> index_of;
    const auto corners = read_stl_corners(file_name);
    for (unsigned int i = 0; i < corners.size(); i += 3)
      {
        std::array<unsigned int, 3> triangle;
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Point<3>             &x = corners[i + k];
            const std::array<double, 3> key{{x[0], x[1], x[2]}};
            const auto [where, inserted] =
              index_of.emplace(key, static_cast<unsigned int>(vertices.size()));
            if (inserted)
              vertices.push_back(x);
            triangle[k] = where->second;
          }
        triangles.push_back(triangle);
      }
    prepare();
  }



  TriangulatedSurface::TriangulatedSurface(
    const std::vector<Point<3>>                    &vertices,
    const std::vector<std::array<unsigned int, 3>> &triangles)
    : vertices(vertices)
    , triangles(triangles)
  {
    prepare();
  }



  void
  TriangulatedSurface::prepare()
  {
    if (triangles.empty())
      throw std::runtime_error("the surface has no triangles");
    // Each directed edge once, each undirected edge twice: closed and
    // consistently oriented.
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> directed;
    for (const auto &triangle : triangles)
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int from = triangle[k], to = triangle[(k + 1) % 3];
          if (from == to)
            throw std::runtime_error("a triangle has two equal corners");
          if (++directed[{from, to}] > 1)
            throw std::runtime_error(
              "the triangles are not oriented consistently (an edge runs "
              "the same way in two of them)");
        }
    for (const auto &[edge, count] : directed)
      if (directed.count({edge.second, edge.first}) == 0)
        throw std::runtime_error("the surface is not closed (an edge belongs "
                                 "to one triangle only)");

    // Outward: a positive enclosed volume.
    double six_volume = 0.;
    for (const auto &triangle : triangles)
      six_volume +=
        vertices[triangle[0]] *
        cross_product_3d(vertices[triangle[1]], vertices[triangle[2]]);
    if (!(std::abs(six_volume) > 0.))
      throw std::runtime_error("the surface encloses no volume");
    if (six_volume < 0.)
      for (auto &triangle : triangles)
        std::swap(triangle[1], triangle[2]);

    face_normals.clear();
    vertex_normals.assign(vertices.size(), Tensor<1, 3>());
    for (const auto &triangle : triangles)
      {
        const Point<3> &a = vertices[triangle[0]], &b = vertices[triangle[1]],
                       &c   = vertices[triangle[2]];
        Tensor<1, 3> normal = cross_product_3d(b - a, c - a);
        if (!(normal.norm() > 0.))
          throw std::runtime_error("a triangle has no area");
        normal /= normal.norm();
        face_normals.push_back(normal);
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Tensor<1, 3> to_next =
              vertices[triangle[(k + 1) % 3]] - vertices[triangle[k]];
            const Tensor<1, 3> to_previous =
              vertices[triangle[(k + 2) % 3]] - vertices[triangle[k]];
            const double angle =
              std::acos(std::clamp((to_next * to_previous) /
                                     (to_next.norm() * to_previous.norm()),
                                   -1.,
                                   1.));
            vertex_normals[triangle[k]] += angle * normal;
          }
      }
    // Each edge's pseudo-normal: the sum of the normals of its triangles.
    std::map<std::pair<unsigned int, unsigned int>, Tensor<1, 3>> edge_sum;
    for (unsigned int t = 0; t < triangles.size(); ++t)
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int from = triangles[t][k],
                             to   = triangles[t][(k + 1) % 3];
          edge_sum[{std::min(from, to), std::max(from, to)}] += face_normals[t];
        }
    edge_normals.resize(triangles.size());
    for (unsigned int t = 0; t < triangles.size(); ++t)
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int from = triangles[t][k],
                             to   = triangles[t][(k + 1) % 3];
          edge_normals[t][k] =
            edge_sum[{std::min(from, to), std::max(from, to)}];
        }

    tree.clear();
    tree_order.resize(triangles.size());
    for (unsigned int t = 0; t < triangles.size(); ++t)
      tree_order[t] = t;
    build_tree(0, triangles.size());
  }



  unsigned int
  TriangulatedSurface::build_tree(const unsigned int first,
                                  const unsigned int count)
  {
    const unsigned int index = tree.size();
    tree.emplace_back();
    TreeNode node;
    node.lower = node.upper = vertices[triangles[tree_order[first]][0]];
    for (unsigned int i = first; i < first + count; ++i)
      for (const unsigned int v : triangles[tree_order[i]])
        for (unsigned int d = 0; d < 3; ++d)
          {
            node.lower[d] = std::min(node.lower[d], vertices[v][d]);
            node.upper[d] = std::max(node.upper[d], vertices[v][d]);
          }
    const unsigned int leaf_size = 4;
    if (count <= leaf_size)
      {
        node.first  = first;
        node.count  = count;
        tree[index] = node;
        return index;
      }
    // Split at the median of the triangles' centroids along the box's
    // longest side.
    unsigned int axis = 0;
    for (unsigned int d = 1; d < 3; ++d)
      if (node.upper[d] - node.lower[d] > node.upper[axis] - node.lower[axis])
        axis = d;
    const auto centroid = [&](const unsigned int t) {
      return vertices[triangles[t][0]][axis] + vertices[triangles[t][1]][axis] +
             vertices[triangles[t][2]][axis];
    };
    const unsigned int half = count / 2;
    std::nth_element(tree_order.begin() + first,
                     tree_order.begin() + first + half,
                     tree_order.begin() + first + count,
                     [&](const unsigned int a, const unsigned int b) {
                       return centroid(a) < centroid(b);
                     });
    node.children[0] = build_tree(first, half);
    node.children[1] = build_tree(first + half, count - half);
    tree[index]      = node;
    return index;
  }



  TriangulatedSurface::Proximity
  TriangulatedSurface::proximity(const Point<3> &x) const
  {
    double            distance_squared = std::numeric_limits<double>::max();
    unsigned int      nearest_triangle = triangles.size();
    NearestOnTriangle nearest{x, 0};
    // The squared distance of x from a node's box.
    const auto box_distance = [&](const TreeNode &node) {
      double sum = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double outside =
            std::max({node.lower[d] - x[d], x[d] - node.upper[d], 0.});
          sum += outside * outside;
        }
      return sum;
    };
    // Depth first, nearer child first; a box farther than the nearest
    // triangle found is skipped (one at the same distance is not: a tie
    // goes to the lowest index, as in a search of all triangles).
    // (The median split keeps the tree's depth at log2 of the triangles,
    // and the stack holds at most one node more than the depth.)
    std::array<unsigned int, 128> stack;
    unsigned int                  n_stacked = 0;
    stack[n_stacked++]                      = 0;
    while (n_stacked > 0)
      {
        const TreeNode &node = tree[stack[--n_stacked]];
        if (box_distance(node) > distance_squared)
          continue;
        if (node.count > 0)
          {
            for (unsigned int i = node.first; i < node.first + node.count; ++i)
              {
                const unsigned int t = tree_order[i];
                const auto         candidate =
                  nearest_on_triangle(x,
                                      vertices[triangles[t][0]],
                                      vertices[triangles[t][1]],
                                      vertices[triangles[t][2]]);
                const double d = (x - candidate.point).norm_square();
                if (d < distance_squared ||
                    (d == distance_squared && t < nearest_triangle))
                  {
                    distance_squared = d;
                    nearest          = candidate;
                    nearest_triangle = t;
                  }
              }
            continue;
          }
        const double near_first  = box_distance(tree[node.children[0]]),
                     near_second = box_distance(tree[node.children[1]]);
        // The nearer child on top of the stack.
        const bool first_nearer = near_first <= near_second;
        stack[n_stacked++]      = node.children[first_nearer ? 1 : 0];
        stack[n_stacked++]      = node.children[first_nearer ? 0 : 1];
      }
    Tensor<1, 3> pseudo_normal;
    if (nearest.feature == 0)
      pseudo_normal = face_normals[nearest_triangle];
    else if (nearest.feature <= 3)
      pseudo_normal =
        vertex_normals[triangles[nearest_triangle][nearest.feature - 1]];
    else
      pseudo_normal = edge_normals[nearest_triangle][nearest.feature - 4];

    Proximity           result;
    const Tensor<1, 3>  offset      = x - nearest.point;
    const double        distance    = std::sqrt(distance_squared);
    const bool          inside      = offset * pseudo_normal < 0.;
    const Tensor<1, 3> &face_normal = face_normals[nearest_triangle];
    result.gap                      = inside ? -distance : distance;
    if (distance == 0.)
      {
        // On the surface: the pseudo-normal.
        result.normal = pseudo_normal / pseudo_normal.norm();
        return result;
      }
    // A face does not turn, nor an edge or a corner within a flat part of
    // the surface (the point straight above or below the face).
    if (nearest.feature == 0 ||
        std::abs(offset * face_normal) >= (1. - 1e-12) * distance)
      {
        result.normal = face_normal;
        return result;
      }
    // At a corner the normal turns with the point in every direction, at
    // an edge in those across the edge: (I - n n - t t) / gap.
    result.normal        = (inside ? -offset : offset) / distance;
    Tensor<2, 3> turning = Tensor<2, 3>(unit_symmetric_tensor<3>()) -
                           outer_product(result.normal, result.normal);
    if (nearest.feature >= 4)
      {
        const unsigned int k = nearest.feature - 4;
        Tensor<1, 3>       tangent =
          vertices[triangles[nearest_triangle][(k + 1) % 3]] -
          vertices[triangles[nearest_triangle][k]];
        tangent /= tangent.norm();
        turning -= outer_product(tangent, tangent);
      }
    result.normal_derivative = turning / result.gap;
    return result;
  }



  std::pair<Point<3>, Point<3>>
  TriangulatedSurface::bounding_box() const
  {
    Point<3> lower = vertices[0], upper = vertices[0];
    for (const auto &vertex : vertices)
      for (unsigned int d = 0; d < 3; ++d)
        {
          lower[d] = std::min(lower[d], vertex[d]);
          upper[d] = std::max(upper[d], vertex[d]);
        }
    return {lower, upper};
  }
} // namespace impm
