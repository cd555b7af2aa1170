#ifndef impm_contact_triangulated_surface_h
#define impm_contact_triangulated_surface_h

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
   * The nearest point is found over all triangles; the sign comes from the
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
    /** Check the mesh, orient it outward and compute the pseudo-normals. */
    void
    prepare();

    std::vector<Point<3>>                    vertices;
    std::vector<std::array<unsigned int, 3>> triangles;
    /** Unit normal of each triangle. */
    std::vector<Tensor<1, 3>> face_normals;
    /** Angle-weighted pseudo-normal of each vertex. */
    std::vector<Tensor<1, 3>> vertex_normals;
    /** Pseudo-normal of each triangle's edges (edge k from corner k to
     *  corner k + 1): the sum of its two triangles' normals. */
    std::vector<std::array<Tensor<1, 3>, 3>> edge_normals;
  };
} // namespace impm

#endif
