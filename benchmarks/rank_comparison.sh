#!/usr/bin/env bash
# Same results on 1 and 2 MPI ranks: runs each given
# parameter file with 1 and with 2 ranks and prints, per statistics.csv
# column, the largest relative difference over all steps (the meshes are
# the same: p4est refines independently of the partition).
# Usage: benchmarks/rank_comparison.sh [build dir] [prm files...]
#   default: the 80-step quarter circle at h = 2^-7 and the two circles demo
set -euo pipefail
build=${1:-build}; shift || true
here=$(cd "$(dirname "$0")/.." && pwd)
files=${*:-$here/parameter_files/willmore_flow/quarter_circle_h7.prm $here/parameter_files/willmore_flow/two_circles_demo.prm}
work=$(mktemp -d)
for prm in $files; do
  name=$(basename "$prm" .prm)
  for ranks in 1 2; do
    sed -e "s|set Output directory = .*|set Output directory = $work/${name}_$ranks|" \
        -e "s|set VTU interval *= .*|set VTU interval = 0|" "$prm" > "$work/${name}_$ranks.prm"
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np $ranks "$build/willmore_flow" \
      "$work/${name}_$ranks.prm" > "$work/${name}_$ranks.log" 2>&1
  done
  /usr/bin/python3 - "$work/${name}_1/statistics.csv" "$work/${name}_2/statistics.csv" "$name" <<'PY'
import csv, math, sys
one = list(csv.DictReader(open(sys.argv[1])))
two = list(csv.DictReader(open(sys.argv[2])))
assert len(one) == len(two), "different numbers of steps"
print(f"{sys.argv[3]}: {len(one) - 1} steps, largest relative difference 1 vs 2 ranks")
for column in ["cells", "dofs", "newton_iterations", "willmore_energy",
               "area_energy", "inside_measure", "l2_error"]:
    worst = 0.0
    for a, b in zip(one, two):
        x, y = float(a[column]), float(b[column])
        if math.isnan(x) and math.isnan(y):
            continue
        worst = max(worst, abs(x - y) / max(abs(x), abs(y), 1e-300))
    print(f"  {column:<18} {worst:.2e}")
PY
done
rm -rf "$work"
