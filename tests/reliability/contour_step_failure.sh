#!/bin/sh
# Usage: contour_step_failure.sh <ranks> <mpiexec> <shape_from_contour>
#                                <work directory>
# A step of shape_from_contour that fails names the step, the sub-step of
# Algorithm 6.1 and the parameters to change, with exit status 1 as other
# runtime failures, on every rank count without a hang
# (doc/shape_from_contour.md, "When a step fails"). The default problem
# on level 5 alone, 3 steps, one step halving:
# - Newton / Maximum iterations = 1: the nested step of sub-step 1 of
#   step 1 does not converge at tau or tau/2 (TimeLoop's message);
# - Model / Mismatch weight = 1e6: the explicit mismatch step of step 1
#   moves U so far that the inner problem (Algorithm 3.1) of the nested
#   step after it (sub-step 3) throws. (With 1e4 this happens in step 3
#   on 1 rank, but on 2 ranks step 1 takes 696 GMRES iterations and
#   succeeds.)
# - Model / Mismatch weight = 1e300: the mismatch step of step 1 makes U
#   infinite (sub-step 2) at tau and tau/2.
ranks="$1"; mpiexec="$2"; program="$3"; work="$4"
. "$(dirname "$0")/common.sh"
rm -rf "$work"; mkdir -p "$work"
base() {
  dir="$1"; shift
  run "$ranks" "$program" --set "Multilevel/Levels=5" \
    --set "Multilevel/Steps per level=3" \
    --set "Newton/Maximum step halvings=1" --set "Output/VTU interval=0" \
    --set "Output directory=$work/$dir" "$@"
}
base newton --set "Newton/Maximum iterations=1"
expect "Newton of the first nested half step" 1 \
  "Step 1 of shape_from_contour \(level 5\) failed in sub-step 1 of 3 of Algorithm 6.1, the nested step of the regularisation with tau/2 = 0.000234375, did not converge. Try a smaller <Time stepping / Tau> .*<Newton / Maximum iterations>.*even after halving the time step 1 times"
base mismatch --set "Model/Mismatch weight=1e6"
expect "the nested step after a too large mismatch step" 1 \
  "Step 1 of shape_from_contour \(level 5\) failed in sub-step 3 of 3 of Algorithm 6.1, .* from the result of the explicit mismatch step, did not converge.*try a smaller <Model / Mismatch weight> or <Time stepping / Tau>.*\(The inner problem \(V for given U, Algorithm 3.1\) did not converge"
base infinite --set "Model/Mismatch weight=1e300"
expect "an infinite mismatch step" 1 \
  "Step 1 of shape_from_contour \(level 5\) failed in sub-step 2 of 3 of Algorithm 6.1, the explicit mismatch step with tau = 0.00046875, made the phase field not finite.*<Model / Mismatch weight>"
exit $failed
