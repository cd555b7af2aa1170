#ifndef impm_core_triangulated_surface_h
#define impm_core_triangulated_surface_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief A closed triangulated surface in 3D, read from an STL file (ASCII
   * or binary): the shape of a rigid body given as a surface mesh.
   *
   * It answers what the contact needs: the signed distance of a point from
   * the surface (negative inside), the outward normal and its derivative.
   * The nearest point is found with a bounding-volume hierarchy of the
   * triangles (the same triangle as a search of all, ties going to the
   * lowest index); the sign comes from the
   * angle-weighted pseudo-normal of the nearest feature (face, edge or
   * vertex), which is exact for a closed, consistently oriented surface.
   * On a face the normal is the face's and does not turn; where the nearest
   * point is on an edge or a vertex the normal is the direction to the
   * point and turns with it: (I - n n) / gap at a vertex, (I - n n - t t) /
   * gap at an edge of tangent t (an edge or a vertex inside a flat part
   * counts as the face).
   */
  class TriangulatedSurface
  {
  public:
    /**
     * @brief Read @p file_name. Throws an std::runtime_error whose text
     * says what is wrong (no such file, not STL, no triangles, a
     * degenerate triangle, an edge not shared by exactly two triangles).
     */
    explicit TriangulatedSurface(const std::string &file_name);

    /**
     * @brief Build from @p vertices and @p triangles (three vertex indices
     * each, counter-clockwise seen from outside, or all clockwise). Throws
     * as the constructor above.
     */
    TriangulatedSurface(
      const std::vector<Point<3>>                    &vertices,
      const std::vector<std::array<unsigned int, 3>> &triangles);

    /** @brief Where a point is relative to the surface. */
    struct Proximity
    {
      /** Signed distance, negative inside. */
      double gap;
      /** Outward unit normal. */
      Tensor<1, 3> normal;
      /** Its derivative with respect to the point. */
      Tensor<2, 3> normal_derivative;
    };

    /** @brief The proximity of @p x. */
    Proximity
    proximity(const Point<3> &x) const;

    /** @brief The smallest box holding the surface. */
    std::pair<Point<3>, Point<3>>
    bounding_box() const;

    /** @brief The vertices (merged: one per position). */
    const std::vector<Point<3>> &
    get_vertices() const
    {
      return vertices;
    }

    /** @brief The triangles, outward oriented. */
    const std::vector<std::array<unsigned int, 3>> &
    get_triangles() const
    {
      return triangles;
    }

  private:
    /** Check the mesh, orient it outward, compute the pseudo-normals and
     *  build the search tree. */
    void
    prepare();

    /** @brief A node of the search tree: a box holding triangles
     *  tree_order[first, first + count) (a leaf) or its two children. */
    struct TreeNode
    {
      /** The box. */
      Point<3> lower, upper;
      /** The triangles of a leaf (count > 0), in tree_order. */
      unsigned int first = 0, count = 0;
      /** The children of an inner node (count == 0). */
      unsigned int children[2] = {0, 0};
    };

    /** @brief Build the tree over tree_order[first, first + count) below
     *  a new node; returns its index. */
    unsigned int
    build_tree(const unsigned int first, const unsigned int count);

    std::vector<Point<3>>                    vertices;
    std::vector<std::array<unsigned int, 3>> triangles;
    /** Unit normal of each triangle. */
    std::vector<Tensor<1, 3>> face_normals;
    /** Angle-weighted pseudo-normal of each vertex. */
    std::vector<Tensor<1, 3>> vertex_normals;
    /** Pseudo-normal of each triangle's edges (edge k from corner k to
     *  corner k + 1): the sum of its two triangles' normals. */
    std::vector<std::array<Tensor<1, 3>, 3>> edge_normals;
    /** The search tree (a bounding-volume hierarchy, root first): the
     *  nearest triangle is found by visiting the boxes nearer than the
     *  nearest triangle found so far, nearer child first. */
    std::vector<TreeNode> tree;
    /** The triangles in the order of the tree's leaves. */
    std::vector<unsigned int> tree_order;
  };
} // namespace impm

#endif
