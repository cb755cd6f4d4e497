#include <cmath>
#include <deal.II/base/mpi.h>
#include <phasefield/time/local_error_estimate.h>

namespace PhaseField
{
  void
  LocalErrorEstimate::record(const Vector &before,
                             const Vector &after,
                             const double  tau)
  {
    last_change.reinit(1);
    last_change.block(0) = after;
    last_change.block(0) -= before;
    last_change.collect_sizes();
    last_tau   = tau;
    has_change = true;
  }



  std::optional<double>
  LocalErrorEstimate::estimate(const Vector &before,
                               const Vector &after,
                               const double  tau,
                               const Vector &lumped_mass) const
  {
    if (!has_change)
      return std::nullopt;
    const double ratio = tau / last_tau;
    // e = D / 2 (the class documentation)
    constexpr double   scale  = 0.5;
    const Vector      &change = last_change.block(0);
    const double      *u      = after.begin();
    const double      *u_k    = before.begin();
    const double      *dk     = change.begin();
    const double      *m      = lumped_mass.begin();
    const unsigned int size   = after.locally_owned_size();
    double             sum    = 0;
    for (unsigned int i = 0; i < size; ++i)
      {
        // D = (U^{k+1} - U^k) - (tau / tau_p) (U^k - U^{k-1})
        const double d = u[i] - u_k[i] - ratio * dk[i];
        sum += m[i] * d * d;
      }
    return scale *
           std::sqrt(
             dealii::Utilities::MPI::sum(sum, after.get_mpi_communicator()));
  }



  std::vector<BlockVector *>
  LocalErrorEstimate::history()
  {
    if (!has_change)
      return {};
    return {&last_change};
  }



  void
  LocalErrorEstimate::forget()
  {
    has_change = false;
  }
} // namespace PhaseField
