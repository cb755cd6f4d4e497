#!/usr/bin/env bash
# Resume on another number of MPI ranks: runs the given parameter file
# uninterrupted on 1 rank, then the same with `Number of steps` = half of
# it (with `Checkpoint / Interval` = that half) on 1 rank, resumed up to
# the full number of steps on 2 ranks, and the other way round (save on 2,
# resume on 1). Prints, per statistics.csv column, the largest relative
# difference of each resumed run to the uninterrupted one.
# Usage: benchmarks/checkpoint_ranks.sh [build dir] [prm file]
#   default: the quarter circle at h = 2^-7 (parameter_files/willmore_flow)
set -euo pipefail
build=${1:-build}; shift || true
here=$(cd "$(dirname "$0")/.." && pwd)
prm=${1:-$here/parameter_files/willmore_flow/quarter_circle_h7.prm}
work=$(mktemp -d)
n_steps=$(sed -n 's/^ *set Number of steps *= *\([0-9]*\).*/\1/p' "$prm")
half=$((n_steps / 2))

# write_prm <name> <steps> <resume>: the parameter file of one run
write_prm() {
  sed -e "s|set Output directory = .*|set Output directory = $work/$1|" \
      -e "s|set VTU interval *= .*|set VTU interval = 0|" \
      -e "s|set Number of steps *= .*|set Number of steps = $2|" "$prm" > "$work/$1_$2.prm"
  printf 'subsection Checkpoint\n  set Interval = %s\n  set Resume = %s\nend\n' \
    "$half" "$3" >> "$work/$1_$2.prm"
}

# run <name> <steps> <resume> <ranks>
run() {
  write_prm "$1" "$2" "$3"
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np "$4" "$build/willmore_flow" \
    "$work/$1_$2.prm" > "$work/$1_$2_$4.log" 2>&1
}

run uninterrupted "$n_steps" false 1
run one_to_two "$half" false 1
run one_to_two "$n_steps" true 2
run two_to_one "$half" false 2
run two_to_one "$n_steps" true 1
for name in one_to_two two_to_one; do
  /usr/bin/python3 - "$work/uninterrupted/statistics.csv" "$work/$name/statistics.csv" "$name" <<'PY'
import csv, math, sys
one = list(csv.DictReader(open(sys.argv[1])))
two = list(csv.DictReader(open(sys.argv[2])))
assert len(one) == len(two), "different numbers of steps"
print(f"{sys.argv[3]}: {len(one) - 1} steps, largest relative difference to the uninterrupted run on 1 rank")
for column in ["time", "cells", "dofs", "newton_iterations", "willmore_energy",
               "area_energy", "inside_measure", "l2_error", "tau"]:
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
