#!/bin/sh
# Usage: stop_signal.sh <ranks> <mpiexec> <willmore_flow> <work directory> [signal]
# SIGTERM (or [signal]: TERM, INT, HUP) stops a run at the next step boundary on all ranks
# (doc/willmore_flow.md, "Output"): willmore_flow (quarter circle at
# level 5, 400 steps, checkpoints every 1000 steps, i.e. none due) gets
# SIGTERM once statistics.csv has 4 rows (on 2 ranks one of the ranks
# gets it, not mpirun, which would kill the ranks 1 s later and stop
# relaying their output: the other rank must stop at the same step). It must exit with status 1 within 60 s, say after which
# step k it stopped, write the checkpoint of step k although none was due,
# and a resume up to step k + 1 must continue from it.
ranks="$1"; mpiexec="$2"; program="$3"; work="$4"; signal="${5:-TERM}"
. "$(dirname "$0")/common.sh"
rm -rf "$work"; mkdir -p "$work"
set -- "$program" --set "Geometry/Shape=quarter circle" \
  --set "Mesh/Finest level=5" --set "Mesh/Coarsest level=3" \
  --set "Output/VTU interval=0" --set "Checkpoint/Interval=1000" \
  --set "Output directory=$work/run"
if [ "$ranks" -eq 1 ]; then
  OMP_NUM_THREADS=1 timeout 60 "$@" --set "Time stepping/Number of steps=400" \
    > "$work/run.log" 2>&1 &
else
  OMP_NUM_THREADS=1 timeout 60 "$mpiexec" --allow-run-as-root \
    --oversubscribe -n "$ranks" "$@" \
    --set "Time stepping/Number of steps=400" > "$work/run.log" 2>&1 &
fi
job=$!
# the child of timeout: the program, or mpirun with the ranks as children
for i in $(seq 1 600); do
  target=$(pgrep -P $job | head -1)
  [ "$ranks" -gt 1 ] && [ -n "$target" ] &&
    target=$(pgrep -P "$target" | tail -1)
  rows=$(cat "$work/run/statistics.csv" 2>/dev/null | wc -l)
  [ -n "$target" ] && [ "$rows" -ge 5 ] && break
  sleep 0.1
done
kill -"$signal" "$target"
wait $job
status=$?
output=$(cat "$work/run.log")
expect "SIG$signal" 1 "Stopped by SIG$signal after step [0-9]+: .*checkpoint of this step is in"
step=$(printf '%s' "$output" | sed -n "s/.*Stopped by SIG$signal after step \\([0-9]*\\).*/\\1/p" | head -1)
[ -n "$step" ] && [ -d "$work/run/checkpoint-$step" ] ||
  { echo "FAIL: no checkpoint-$step"; failed=1; }
run "$ranks" "$@" --set "Checkpoint/Resume=true" \
  --set "Time stepping/Number of steps=$((step + 1))"
expect "resume after SIG$signal" 0 "resuming after step $step"
exit $failed
