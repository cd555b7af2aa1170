#ifndef impm_system_near_null_space_h
#define impm_system_near_null_space_h

#include <vector>

namespace impm
{
  /**
   * @brief The near null space of an elasticity system for algebraic
   * multigrid: its rigid-body modes (dim translations, then 1 rotation in
   * 2D or 3 in 3D) on this process's rows.
   */
  struct NearNullSpace
  {
    /** Number of modes. */
    unsigned int n_modes = 0;
    /** This process's rows of the system. */
    unsigned int n_rows = 0;
    /** The modes, one after the other: mode m's value in row r at
     *  m * n_rows + r. */
    std::vector<double> values;
  };

} // namespace impm

#endif
