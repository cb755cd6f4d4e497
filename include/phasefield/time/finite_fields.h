#ifndef phasefield_time_finite_fields_h
#define phasefield_time_finite_fields_h

#include <phasefield/core/linear_algebra.h>
#include <string>
#include <utility>
#include <vector>

namespace PhaseField
{
  /**
   * Stop before output that would contain NaN or Inf (also an entry beyond
   * the range of the VTU file's 32-bit floats, 3.4e38): throws (on every
   * rank, the count is summed over the vectors' communicator) a
   * dealii::ExceptionBase whose message names step @p step, the first
   * field of @p fields with a non-finite entry, the number of such entries
   * and the parameter to change, if any entry of any field is not finite.
   * Collective.
   */
  void
  check_output_fields_finite(
    const unsigned int                                         step,
    const std::vector<std::pair<std::string, const Vector *>> &fields);
} // namespace PhaseField

#endif
