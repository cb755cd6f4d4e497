#!/usr/bin/env bash
# Time to accuracy on the quarter circle (doc/willmore_flow.md, "Step
# control"): the shipped parameter_files/willmore_flow/quarter_circle_h<L>.prm
# to the end time T = 80 h^2 with the fixed steps of Tau = h^2 and with the
# adaptive control at each tolerance, 2 MPI ranks, no VTU output. Prints one
# row per run: level, control, tolerance, steps, Newton iterations (sum and
# max per step), halved steps, final l2_error, wall seconds.
# Usage: [TOLERANCES="3e-5 1e-4 3e-4"] benchmarks/step_control.sh [build dir] [levels...]
#   e.g. benchmarks/step_control.sh build 7 8 9
set -euo pipefail
build=${1:-build}; shift || true
levels=${*:-8 9}
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-5s %-9s %9s %6s %7s %4s %8s %12s %8s\n' level control tolerance steps newton max halved l2_error wall_s
for level in $levels; do
  for tolerance in fixed ${TOLERANCES:-3e-5 1e-4 3e-4}; do
    settings=(--set "Time stepping/End time=80*h^2" --set "Output/VTU interval=0"
              --set "Output directory=$work/out")
    control=fixed
    if [ "$tolerance" != fixed ]; then
      control=adaptive
      settings+=(--set "Time stepping/Step control=adaptive"
                 --set "Time stepping/Tolerance=$tolerance")
    fi
    rm -rf "$work/out"
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np 2 "$build/willmore_flow" \
      "$here/parameter_files/willmore_flow/quarter_circle_h$level.prm" \
      "${settings[@]}" > "$work/log" 2>&1
    /usr/bin/python3 - "$work/out/statistics.csv" "$level" "$control" "$tolerance" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))[1:]
newton = [float(r["newton_iterations"]) for r in rows]
halved = sum(float(r["step_halvings"]) > 0 for r in rows)
tolerance = "-" if sys.argv[3] == "fixed" else sys.argv[4]
print("%-5s %-9s %9s %6d %7d %4d %8d %12.4e %8.2f" % (
    sys.argv[2], sys.argv[3], tolerance, len(rows), sum(newton), max(newton),
    halved, float(rows[-1]["l2_error"]), float(rows[-1]["wall_seconds"])))
PY
  done
done
