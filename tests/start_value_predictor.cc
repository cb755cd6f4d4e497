// StartValuePredictor, the extrapolated start value of a time step
// (doc/willmore_flow.md, "Extrapolated start"), on states of two fields
// (U, P) of three entries each: U = (tanh(0 - c), tanh(1 - c), 1), a
// profile whose interface is at c, and a node far from it (U = 1), P =
// (p, 0, 0). Expected values, derived by hand (and a pocket calculator):
// - c = 0, 0.4, 0.6 and p = 0, 10, 15, steps of size 0.1: theta =
//   |dU_2| / |dU_1| = 0.5034 (l2 norms of the U changes), and the start
//   of step 3 moves the interface as the last step did, by theta 0.2:
//   U = tanh(x - 0.7007) = (-0.6048 0.2907 1), P = 15 + 5 theta = 17.517.
//   The far node stays at 1 exactly. The linear extrapolation (Newton's
//   method) gives U_2 + theta (U_2 - U_1) = (-0.6161 0.3009 1) instead;
// - no prediction after one change only, for a step of another size,
//   after forget(), or after the first change recorded for another
//   extrapolation; history() holds one vector after a step, none after
//   forget();
// - growing changes (c = 1.1: |dU_3| / |dU_2| = 2.46): theta is capped at
//   1, U = tanh(x - 1.6) = (-0.9217 -0.5370 1), P = 15;
// - a step of another size (0.05) starts the history anew: after it, one
//   more step of that size is needed before a prediction (c = 1.1 -> 0.6,
//   predicted c = 0.1: U = (-0.09967 0.7163 1));
// - a stationary history (no change in the step before) predicts nothing.

#include "tests.h"

#include <cmath>
#include <deal.II/base/index_set.h>
#include <phasefield/time/start_value_predictor.h>

using namespace PhaseField;
using BlockVector = PhaseField::BlockVector;

namespace
{
  /** The profile with its interface at @p c and P = (@p p, 0, 0). */
  BlockVector
  state(const double c, const double p)
  {
    dealii::IndexSet all(3);
    all.add_range(0, 3);
    BlockVector s(std::vector<dealii::IndexSet>{all, all}, MPI_COMM_WORLD);
    s.block(0)[0] = std::tanh(0 - c);
    s.block(0)[1] = std::tanh(1 - c);
    s.block(0)[2] = 1;
    s.block(1)[0] = p;
    s.compress(dealii::VectorOperation::insert);
    return s;
  }



  /** The prediction from @p last for a step of size @p tau, or "none". */
  void
  print_prediction(const std::string         &label,
                   const StartValuePredictor &predictor,
                   const BlockVector         &last,
                   const double               tau)
  {
    BlockVector start = last;
    Testing::log() << label << ": ";
    if (!predictor.predict(start, tau))
      Testing::log() << "none" << std::endl;
    else
      Testing::log() << start.block(0)[0] << ' ' << start.block(0)[1] << ' '
                     << start.block(0)[2] << " | " << start.block(1)[0]
                     << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const BlockVector                        s0 = state(0, 0);
  const BlockVector                        s1 = state(0.4, 10);
  const BlockVector                        s2 = state(0.6, 15);
  const BlockVector                        s3 = state(1.1, 15);
  constexpr auto      profile                 = StartExtrapolation::profile;
  constexpr auto      linear                  = StartExtrapolation::linear;
  StartValuePredictor predictor;
  predictor.record(s0, s1, 0.1, profile);
  print_prediction("one change", predictor, s1, 0.1);
  predictor.record(s1, s2, 0.1, profile);
  print_prediction("decaying changes", predictor, s2, 0.1);
  print_prediction("another step size", predictor, s2, 0.05);
  predictor.record(s2, s3, 0.1, profile);
  print_prediction("growing changes", predictor, s3, 0.1);
  Testing::log() << "history: " << predictor.history().size() << std::endl;
  predictor.forget();
  print_prediction("after forget", predictor, s3, 0.1);
  Testing::log() << "history after forget: " << predictor.history().size()
                 << std::endl;

  StartValuePredictor linear_predictor;
  linear_predictor.record(s0, s1, 0.1, linear);
  linear_predictor.record(s1, s2, 0.1, linear);
  print_prediction("decaying changes, linear", linear_predictor, s2, 0.1);
  linear_predictor.record(s2, s3, 0.1, profile);
  print_prediction("first step of another extrapolation",
                   linear_predictor,
                   s3,
                   0.1);

  StartValuePredictor sizes;
  sizes.record(s0, s1, 0.1, profile);
  sizes.record(s1, s2, 0.1, profile);
  sizes.record(s2, s3, 0.05, profile);
  print_prediction("first step of a new size", sizes, s3, 0.05);
  sizes.record(s3, s2, 0.05, profile);
  print_prediction("second step of it", sizes, s2, 0.05);

  StartValuePredictor stationary;
  stationary.record(s1, s1, 0.1, profile);
  stationary.record(s1, s2, 0.1, profile);
  print_prediction("after a step without change", stationary, s2, 0.1);
}
