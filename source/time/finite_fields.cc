#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <limits>
#include <phasefield/time/finite_fields.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * Number of entries of @p v on all ranks that are not finite or not
     * finite as the 32-bit floats of a VTU file (|x| > 3.4e38).
     */
    unsigned long
    n_non_finite(const Vector &v)
    {
      constexpr double    largest = std::numeric_limits<float>::max();
      const unsigned long local =
        std::count_if(v.begin(), v.end(), [](const double x) {
          return !(std::abs(x) <= largest);
        });
      return Utilities::MPI::sum(local, v.get_mpi_communicator());
    }
  } // namespace



  void
  check_output_fields_finite(
    const unsigned int                                         step,
    const std::vector<std::pair<std::string, const Vector *>> &fields)
  {
    for (const auto &[name, vector] : fields)
      {
        const unsigned long n = n_non_finite(*vector);
        AssertThrow(
          n == 0,
          ExcMessage(
            "Step " + std::to_string(step) + ": the output field <" + name +
            "> has " + std::to_string(n) +
            " entries that are NaN or Inf (or beyond the 3.4e38 of the "
            "VTU file's 32-bit floats); no VTU output of this "
            "step was written (the output and statistics up to the "
            "previous step are complete). Try a smaller "
            "<Time stepping / Tau>" +
            (name == "curvature" ?
               std::string(" (the curvature field is computed "
                           "with a division by <Time stepping / "
                           "Inner tau> or <Phase field / "
                           "Epsilon>)") :
               std::string()) +
            "."));
      }
  }
} // namespace PhaseField
