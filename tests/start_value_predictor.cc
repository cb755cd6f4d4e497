// StartValuePredictor, the extrapolated start value of a time step
// (doc/willmore_flow.md, "Extrapolated start"), on states of two fields
// (U, P) of two entries each. Expected values, derived by hand:
// - states S_0 = (0 0 | 0 0), S_1 = (1 0 | 10 0), S_2 = (1.5 0 | 15 0),
//   steps of size 0.1: theta = |dU_2| / |dU_1| = 0.5 / 1, and the start of
//   step 3 is S_2 + 0.5 (0.5 0 | 5 0) = (1.75 0 | 17.5 0), P extrapolated
//   with U's theta;
// - no prediction after one change only, for a step of another size, or
//   after forget() (the mesh changed);
// - growing changes (S_3 = S_2 + (0 1 | 0 0), |dU| = 1 > 0.5): theta is
//   capped at 1, the linear extrapolation S_3 + (0 1 | 0 0) = (1.5 2 | 15
//   0);
// - a step of another size (0.05) starts the history anew: after it, one
//   more step of that size is needed before a prediction;
// - a stationary history (no change in the step before) predicts nothing.

#include "tests.h"

#include <deal.II/base/index_set.h>
#include <phasefield/time/start_value_predictor.h>

using namespace PhaseField;
using BlockVector = StartValuePredictor::BlockVector;

namespace
{
  BlockVector
  state(const double u0, const double u1, const double p0, const double p1)
  {
    dealii::IndexSet all(2);
    all.add_range(0, 2);
    BlockVector s(std::vector<dealii::IndexSet>{all, all}, MPI_COMM_WORLD);
    s.block(0)[0] = u0;
    s.block(0)[1] = u1;
    s.block(1)[0] = p0;
    s.block(1)[1] = p1;
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
      Testing::log() << start.block(0)[0] << ' ' << start.block(0)[1] << " | "
                     << start.block(1)[0] << ' ' << start.block(1)[1]
                     << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const BlockVector                        s0 = state(0, 0, 0, 0);
  const BlockVector                        s1 = state(1, 0, 10, 0);
  const BlockVector                        s2 = state(1.5, 0, 15, 0);
  const BlockVector                        s3 = state(1.5, 1, 15, 0);
  StartValuePredictor                      predictor;
  predictor.record(s0, s1, 0.1);
  print_prediction("one change", predictor, s1, 0.1);
  predictor.record(s1, s2, 0.1);
  print_prediction("decaying changes", predictor, s2, 0.1);
  print_prediction("another step size", predictor, s2, 0.05);
  predictor.record(s2, s3, 0.1);
  print_prediction("growing changes", predictor, s3, 0.1);
  predictor.forget();
  print_prediction("after forget", predictor, s3, 0.1);

  StartValuePredictor sizes;
  sizes.record(s0, s1, 0.1);
  sizes.record(s1, s2, 0.1);
  sizes.record(s2, s3, 0.05);
  print_prediction("first step of a new size", sizes, s3, 0.05);
  sizes.record(s3, s2, 0.05);
  print_prediction("second step of it", sizes, s2, 0.05);

  StartValuePredictor stationary;
  stationary.record(s1, s1, 0.1);
  stationary.record(s1, s2, 0.1);
  print_prediction("after a step without change", stationary, s2, 0.1);
}
