#!/usr/bin/env bash
# Run one willmore_flow case with two builds and compare their
# statistics.csv (a refactoring that may not change any result, issue 49):
# every column but wall_seconds, linear_iterations and residual_norm must
# be identical; the linear iterations and wall times of both are printed
# side by side. The last two columns are not reproducible from run to run
# of one build on 2 ranks: the quarter circle at level 7 gave 22 and 23
# GMRES iterations in step 1 and final residuals differing in the fourth
# digit in two runs of the same binary (the Newton counts and energies were
# identical).
# Usage: benchmarks/compare_builds.sh <build A> <build B> <case> [level]
#   case: quarter_circle (parameter_files/willmore_flow/quarter_circle_h<level>.prm)
#         sphere (the level-<level> sphere of benchmarks/solver_levels.sh,
#                 r = 0.35, eps = 4h, tau = 0.03h, ttau = h^2, 10 steps)
#   e.g. benchmarks/compare_builds.sh ../base/build build quarter_circle 9
# Columns: case, level, steps, Newton iterations (B), linear iterations
# (A, B), last Willmore energy (B), wall seconds (A, B), and whether the
# compared columns are identical.
set -euo pipefail
a=$1; b=$2; case=$3; level=${4:-7}
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {
  local build=$1 out=$2
  if [ "$case" = quarter_circle ]; then
    args=("$here/parameter_files/willmore_flow/quarter_circle_h$level.prm"
          --set "Output/VTU interval=0")
  else
    args=(--set "Dimension=3" --set "Geometry/Shape=sphere"
          --set "Geometry/Radius=0.35" --set "Mesh/Finest level=$level"
          --set "Mesh/Coarsest level=3" --set "Phase field/Epsilon=4*h"
          --set "Time stepping/Tau=0.03*h" --set "Time stepping/Inner tau=h^2"
          --set "Time stepping/Number of steps=${STEPS:-10}"
          --set "Output/VTU interval=0")
  fi
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np 2 "$build/willmore_flow" \
    "${args[@]}" --set "Output directory=$out" > "$out.log" 2>&1
}
run "$a" "$work/a"
run "$b" "$work/b"
/usr/bin/python3 - "$work/a/statistics.csv" "$work/b/statistics.csv" "$case" "$level" <<'PY'
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
varying = ("wall_seconds", "linear_iterations", "residual_norm")
columns = [c for c in a[0] if c not in varying]
different = sorted({c for ra, rb in zip(a, b) for c in columns if ra[c] != rb[c]})
same = len(a) == len(b) and not different
total = lambda rows, c: sum(int(float(r[c])) for r in rows[1:])
print(f'{sys.argv[3]:<15} {sys.argv[4]:>5} {len(b) - 1:>5} '
      f'{total(b, "newton_iterations"):>6} {total(a, "linear_iterations"):>8} '
      f'{total(b, "linear_iterations"):>8} {b[-1]["willmore_energy"]:>12} '
      f'{float(a[-1]["wall_seconds"]):>8.1f} {float(b[-1]["wall_seconds"]):>8.1f}  '
      + ("identical" if same else "DIFFERENT: " + ",".join(different)))
PY
