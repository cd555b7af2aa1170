#ifndef impm_base_point_field_h
#define impm_base_point_field_h

#include <string>
#include <vector>

namespace impm
{
  /**
   * @brief One quantity stored at every material point on behalf of whoever
   * declares it: a material's state variables (Material::state_fields()), a
   * coupling's per-point history (Coupling::point_fields()).
   *
   * The points' property layout (PointLayout), the point files' fields and
   * the checkpoint's check of the layout follow from these declarations;
   * nothing else needs to change to store one more quantity.
   */
  struct PointField
  {
    /**
     * The field's name: its column in the point files (if @p written) and
     * the name its owner looks it up by; lower case with underscores, as
     * the point files' other fields.
     */
    std::string name;
    /** Entries per point. */
    unsigned int n_components = 1;
    /**
     * Whether the point files may write it (`Output/Fields` names it or
     * `all`): a scalar as one array, more components as `name_0`,
     * `name_1`, ...; false for internal data (a coupling's history of face
     * tractions).
     */
    bool written = true;
  };

  /** @brief The declarations of one owner, in the order of its storage. */
  using PointFields = std::vector<PointField>;
} // namespace impm

#endif
