#ifndef impm_base_names_h
#define impm_base_names_h

#include <array>
#include <string>

namespace impm
{
  /**
   * @brief The names of coordinate axes and grid faces, used in scenes,
   * messages, `steps.csv` columns and the test summary alike.
   *
   * Faces are numbered as deal.II's boundary ids of a hyper-rectangle:
   * 2d is the lower face normal to axis d, 2d+1 the upper one. A face's name
   * is its axis and the sign of its outward normal: x-, x+, y-, y+, z-, z+.
   */
  namespace Names
  {
    /** The axis names x, y, z. */
    constexpr std::array<const char *, 3> axes = {{"x", "y", "z"}};

    /** The face names in boundary-id order. */
    constexpr std::array<const char *, 6> faces = {
      {"x-", "x+", "y-", "y+", "z-", "z+"}};

    /** @brief The name of axis @p d. */
    inline std::string
    axis(const unsigned int d)
    {
      return axes.at(d);
    }

    /** @brief The name of face @p f (boundary id). */
    inline std::string
    face(const unsigned int f)
    {
      return faces.at(f);
    }

    /** @brief The axis normal to face @p f. */
    constexpr unsigned int
    face_axis(const unsigned int f)
    {
      return f / 2;
    }

    /** @brief The sign of the outward normal of face @p f (-1 or +1). */
    constexpr double
    face_sign(const unsigned int f)
    {
      return f % 2 == 0 ? -1. : 1.;
    }

    /**
     * @brief The boundary id of the face called @p name; an unknown name
     * returns faces.size().
     */
    inline unsigned int
    face_from_name(const std::string &name)
    {
      for (unsigned int f = 0; f < faces.size(); ++f)
        if (name == faces[f])
          return f;
      return faces.size();
    }
  } // namespace Names
} // namespace impm

#endif
