#!/bin/sh
# Usage: checkpoint_rank_change.sh <mpiexec> <program> <prm file> <steps>
#                                  <work directory> [--set ...]
# Resume on another number of MPI ranks (doc/willmore_flow.md, "Checkpoint
# and resume"): runs <prm file> (with the extra --set options) for <steps>
# steps uninterrupted on 1 rank, then for half the steps on 1 rank and
# resumed to <steps> on 2 ranks, and the other way round (2, then 1). All
# runs write a checkpoint every <steps>/2 steps, so that the uninterrupted
# run also continues from a re-read checkpoint. Prints per statistics.csv
# column the largest relative difference of each resumed run to the
# uninterrupted one and fails unless time, tau, cells, DoFs and Newton
# iterations are equal and the energies and inside measure agree to 1e-8
# relative and l2_error to 1e-6 relative (the direct solver's round-off on
# 2 ranks; the Newton tolerance is 1e-8 relative). Used by the ctest
# checkpoint_rank_change and by benchmarks/checkpoint_ranks.sh.
mpiexec="$1"; program="$2"; prm="$3"; steps="$4"; work="$5"
shift 5
half=$((steps / 2))
rm -rf "$work"
mkdir -p "$work"

# run <name> <steps> <resume> <ranks> [--set ...]
run() {
  name="$1"; n="$2"; resume="$3"; ranks="$4"
  shift 4
  OMP_NUM_THREADS=1 timeout 300 "$mpiexec" --allow-run-as-root \
    --oversubscribe -n "$ranks" "$program" "$prm" "$@" \
    --set "Output directory=$work/$name" --set "Output/VTU interval=0" \
    --set "Time stepping/Number of steps=$n" \
    --set "Checkpoint/Interval=$half" --set "Checkpoint/Resume=$resume" \
    > "$work/${name}_${n}_$ranks.log" 2>&1 ||
    { echo "FAIL: run $name ($n steps, $ranks ranks)"
      cat "$work/${name}_${n}_$ranks.log"; exit 1; }
}

run uninterrupted "$steps" false 1 "$@"
run one_to_two "$half" false 1 "$@"
run one_to_two "$steps" true 2 "$@"
run two_to_one "$half" false 2 "$@"
run two_to_one "$steps" true 1 "$@"
/usr/bin/python3 - "$work" <<'PY'
import csv, math, sys
work = sys.argv[1]
def rows(name):
    return list(csv.DictReader(open(f"{work}/{name}/statistics.csv")))
reference = rows("uninterrupted")
# column: largest relative difference allowed
limits = {"time": 0, "tau": 0, "cells": 0, "dofs": 0, "newton_iterations": 0,
          "willmore_energy": 1e-8, "area_energy": 1e-8,
          "inside_measure": 1e-8, "l2_error": 1e-6}
failed = False
for name in ["one_to_two", "two_to_one"]:
    resumed = rows(name)
    print(f"{name}: {len(resumed) - 1} of {len(reference) - 1} steps, "
          "largest relative difference to the uninterrupted run on 1 rank")
    if [r["step"] for r in resumed] != [r["step"] for r in reference]:
        print("  FAIL: the steps differ")
        failed = True
        continue
    for column, limit in limits.items():
        worst = 0.0
        for a, b in zip(reference, resumed):
            x, y = float(a[column]), float(b[column])
            if math.isnan(x) and math.isnan(y):
                continue
            worst = max(worst, abs(x - y) / max(abs(x), abs(y), 1e-300))
        verdict = "ok" if worst <= limit else f"FAIL (limit {limit:.0e})"
        failed = failed or worst > limit
        print(f"  {column:<18} {worst:.2e} {verdict}")
sys.exit(1 if failed else 0)
PY
