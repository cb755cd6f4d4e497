// The local error estimate of the adaptive step control
// (time/local_error_estimate.h) on the implicit Euler method for
// y' = -y at 20 nodes, y(0) = sin(i + 1), lumped mass 1/20 each: a step of
// size tau_p from y(0), then a step of size tau. The estimate of the second
// step is compared with its true local error ||y2 - exp(-tau) y1||_L2. Both
// are of order tau^2 and their ratio tends to 1 with tau, whatever
// tau / tau_p. The ratios printed are those of the closed form: for the
// implicit Euler method on y' = lambda y, with a = 1 / (1 - lambda tau) and
// b = 1 / (1 - lambda tau_p), the estimate is
// |b a - b - (tau / tau_p) (b - 1)| b ||y(0)|| / 2 = |lambda tau (a - 1)| b
// ||y(0)|| / 2 and the true error |a - exp(lambda tau)| b ||y(0)||
// (tau = 0.2: 1.14135; 0.1: 1.06864; 0.05: 1.03382, for tau_p = tau,
// tau / 2 and 2 tau alike). An estimate with another scale, sign or norm,
// or one that depends on tau_p, changes them; a missing history gives none.

#include "tests.h"

#include <deal.II/base/index_set.h>
#include <phasefield/time/local_error_estimate.h>

namespace
{
  constexpr unsigned int n_nodes = 20;
  constexpr double       lambda  = -1;

  /** The nodal values f(i) on the locally owned part of @p layout. */
  template <typename F>
  PhaseField::Vector
  nodal(const PhaseField::Vector &layout, const F &f)
  {
    PhaseField::Vector v(layout);
    for (const auto i : v.locally_owned_elements())
      v[i] = f(i);
    v.compress(dealii::VectorOperation::insert);
    return v;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       n_ranks =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const unsigned int rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  dealii::IndexSet owned(n_nodes);
  owned.add_range(rank * n_nodes / n_ranks, (rank + 1) * n_nodes / n_ranks);
  const PhaseField::Vector layout(owned, MPI_COMM_WORLD);
  const PhaseField::Vector mass =
    nodal(layout, [](const unsigned int) { return 1. / n_nodes; });
  const PhaseField::Vector y0 =
    nodal(layout, [](const unsigned int i) { return std::sin(i + 1.); });

  PhaseField::LocalErrorEstimate estimate;
  Testing::log() << "without a recorded step: "
                 << (estimate.estimate(y0, y0, 0.1, mass) ? "an estimate" :
                                                            "none")
                 << std::endl;
  Testing::log() << "tau_p    tau     estimate     true error   ratio"
                 << std::endl;
  for (const auto &[tau_p, tau] : std::vector<std::pair<double, double>>{
         {0.2, 0.2}, {0.1, 0.1}, {0.05, 0.05}, {0.1, 0.05}, {0.05, 0.1}})
    {
      PhaseField::Vector y1(y0), y2(y0), exact(y0), error(y0);
      y1 *= 1 / (1 - lambda * tau_p);
      y2 = y1;
      y2 *= 1 / (1 - lambda * tau);
      exact = y1;
      exact *= std::exp(lambda * tau);
      error = y2;
      error -= exact;
      double local = 0;
      for (const auto i : error.locally_owned_elements())
        local += error[i] * error[i] / n_nodes;
      const double true_error =
        std::sqrt(dealii::Utilities::MPI::sum(local, MPI_COMM_WORLD));
      estimate.forget();
      estimate.record(y0, y1, tau_p);
      const double e = *estimate.estimate(y1, y2, tau, mass);
      Testing::log() << std::setw(8) << tau_p << std::setw(8) << tau
                     << std::setw(13) << e << std::setw(13) << true_error
                     << std::setw(9) << e / true_error << std::endl;
    }
}
