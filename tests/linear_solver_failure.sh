#!/bin/sh
# Usage: linear_solver_failure.sh <ranks> <mpiexec> <willmore_flow> <dir>
# A linear-solver failure halves the time step instead of aborting the run
# (doc/willmore_flow.md, "Newton's method"). The iterative solver is
# limited to 7 CG iterations. With the Eisenstat-Walker forcing terms of
# the inexact Newton method (loose solves first) the sixth Newton
# iteration of step 1, the first solve tight enough to need more, fails,
# while the inner problem for V at step 0 does not (with a coarsest
# multigrid level of at most 200 unknowns, the AMG of this 2D level-5 mesh
# is not a direct solve). With the 6-sweep cycles of the Schur
# preconditioner step 1 converges at a limit of 8 (6 Newton, 29 CG
# iterations), hence 7. Step 1 is
# the first step from the initial data, so the descent method takes over
# from its start: it raises its shift where the linear solver does not
# converge (reported) and finishes the step. Step 2 then fails in the
# same way at tau, tau/2 and tau/4 (no descent method: that is for the
# first step only); in each attempt Newton's method reports "the linear
# solver failed". The run must stop with the documented message naming
# step 2 and exit status 1, within 60 s, with statistics.csv complete up
# to step 1. (Until the Eisenstat-Walker forcing, a limit of 10 made
# step 1 fail in all three attempts.)
ranks="$1"; mpiexec="$2"; program="$3"; directory="$4"
time_limit=60
expected_status=1
rm -rf "$directory"
set -- "$program" \
  --set "Dimension=2" --set "Geometry/Shape=quarter circle" \
  --set "Mesh/Finest level=5" --set "Mesh/Coarsest level=3" \
  --set "Time stepping/Number of steps=2" \
  --set "Linear solver/Type=iterative" \
  --set "Linear solver/Maximum iterations=7" \
  --set "Newton/Maximum step halvings=2" \
  --set "Output directory=$directory"
if [ "$ranks" -eq 1 ]; then
  output=$(OMP_NUM_THREADS=1 timeout $time_limit "$@" 2>&1)
else
  output=$(OMP_NUM_THREADS=1 timeout $time_limit "$mpiexec" \
    --allow-run-as-root --oversubscribe -n "$ranks" "$@" 2>&1)
fi
status=$?
fail() { echo "FAIL on $ranks rank(s): $1"; echo "$output"; exit 1; }
[ $status -eq 124 ] && fail "timeout after $time_limit s"
[ $status -eq $expected_status ] ||
  fail "exit status $status (expected $expected_status)"
failures=$(printf '%s\n' "$output" | grep -c "the linear solver failed")
[ "$failures" -eq 4 ] ||
  fail "\"the linear solver failed\" printed $failures times (expected 4)"
fallbacks=$(printf '%s\n' "$output" |
  grep -c "Newton's method failed: the descent method from the start of the step")
[ "$fallbacks" -eq 1 ] ||
  fail "the descent method took over $fallbacks times (expected 1)"
printf '%s\n' "$output" |
  grep -q "the linear solver did not converge (residual .* after 7 iterations), shift" ||
  fail "the descent method did not report a raised shift after a linear-solver failure"
for tau in 0.000488 0.000244; do
  printf '%s\n' "$output" | grep -q \
    "step 2: the solver of the nested scheme did not converge, retrying with half the time step, tau = $tau" ||
    fail "no retry of step 2 with tau = $tau"
done
printf '%s\n' "$output" | grep -q "Step 2: the solver of the nested scheme did not converge even after halving the time step 2 times" ||
  fail "no final message naming step 2 and the 2 halvings"
rows=$(wc -l < "$directory/statistics.csv")
[ "$rows" -eq 3 ] ||
  fail "statistics.csv has $rows lines (expected the header, steps 0 and 1)"
echo "OK on $ranks rank(s): step 1 finished by the descent method, step 2" \
  "retried twice with half the step after linear-solver failures, then exit" \
  "status $status with the message"
