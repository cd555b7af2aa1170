#ifndef impm_coupling_step_refusal_h
#define impm_coupling_step_refusal_h

#include <string>

namespace impm
{
  /**
   * @brief Why a coupling refuses a converged load step
   * (Coupling::refuse_step()): a rigid body that moved too far in it, a
   * material point left inside a body.
   */
  struct StepRefusal
  {
    /** The reason, a sentence for the user (empty: the step is accepted). */
    std::string reason;
    /** Whether a smaller step may be accepted (the step control then cuts
     *  the step); if not, the run stops with the reason. */
    bool smaller_step_may_pass = true;

    /** @brief Whether the step is refused. */
    bool
    refused() const
    {
      return !reason.empty();
    }
  };
} // namespace impm

#endif
