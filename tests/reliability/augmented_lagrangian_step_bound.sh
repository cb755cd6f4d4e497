#!/bin/sh
# Usage: augmented_lagrangian_step_bound.sh <ranks> <mpiexec> <willmore_flow>
#                                           <work directory>
# Every step of the augmented Lagrangian ends (doc/willmore_flow.md,
# "Penalty per step"): a sphere of radius 0.3 in 3D on a mesh far too
# coarse for its epsilon (levels 2-4, Epsilon = 1.5 h, Band width 2), whose
# first step the scheme cannot take, ran for more than 15 minutes in one
# attempt before the trust-region and CG iterations of an attempt were
# bounded. Now the run ends within the time limit, with exit status 0 or
# with exit status 1 and the message of a failed step.
ranks="$1"; mpiexec="$2"; program="$3"; work="$4"
. "$(dirname "$0")/common.sh"
rm -rf "$work"; mkdir -p "$work"
# one step of about 560 trust-region iterations in four attempts
time_limit=360
run "$ranks" "$program" --set "Dimension=3" --set "Geometry/Shape=sphere" \
  --set "Geometry/Radius=0.3" --set "Mesh/Coarsest level=2" \
  --set "Mesh/Finest level=4" --set "Mesh/Band width=2" \
  --set "Phase field/Epsilon=1.5*h" \
  --set "Time stepping/Scheme=augmented lagrangian" \
  --set "Time stepping/Number of steps=1" --set "Output/VTU interval=0" \
  --set "Output directory=$work/run"
# the attempt that did not end is now stopped by <Maximum CG iterations
# per step> and halved (1 rank: 19564 CG iterations in its third outer
# iteration); the half step converges
if [ "$status" -eq 1 ]; then
  expect "a step the augmented Lagrangian cannot take" 1 "step 1"
else
  expect "a step the augmented Lagrangian cannot take" 0 "Peak resident memory"
fi
exit $failed
