#!/usr/bin/env bash
# The extrapolated start value in edge restoration (issue 14; doc/
# willmore_flow.md, "Extrapolated start"): runs a shipped edge_restoration
# file with `Time stepping / Extrapolated start` true and false and prints
# per run the Newton (descent) iterations of every step, the final
# weighted energy W + eta A, the time loop's wall clock at the last step
# and the whole run's wall time.
# FILE: damaged_circle (default) or cross (parameter_files/edge_restoration),
# LEVEL: `Mesh / Finest level` (default 9; the files' own is 10),
# STEPS: number of steps (default 6), NP MPI ranks (default 2), no VTU
# output. Level 10 with 30 steps takes about 20 minutes per run on 2 ranks.
# Usage: [FILE=...] [LEVEL=l] [STEPS=n] [NP=n] benchmarks/restoration_start.sh
#          [build dir]
set -uo pipefail
build=${1:-build}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
prm=$source_dir/parameter_files/edge_restoration/${FILE:-damaged_circle}.prm
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-13s %-60s %16s %10s %8s\n' extrapolated "Newton iterations per step" \
  weighted_energy loop_s run_s
for extrapolated in true false; do
  out=$work/$extrapolated
  /usr/bin/time -f "%e" -o "$out.time" env OMP_NUM_THREADS=1 \
    mpirun --allow-run-as-root --oversubscribe -np "${NP:-2}" \
    "$build/edge_restoration" "$prm" \
    --set "Mesh/Finest level=${LEVEL:-9}" \
    --set "Time stepping/Number of steps=${STEPS:-6}" \
    --set "Time stepping/Extrapolated start=$extrapolated" \
    --set "Output/VTU interval=0" --set "Output directory=$out" \
    > "$out.log" 2>&1 || { echo "$extrapolated: FAILED ($out.log)"; continue; }
  # columns of statistics.csv by name; rows after step 0
  read -r iterations energy loop_s < <(awk -F, '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    NR > 2  { it = it $c["newton_iterations"] "_" }
    END     { print it, $c["weighted_energy"], $c["wall_seconds"] }' \
    "$out/statistics.csv")
  iterations=${iterations//_/ }
  printf '%-13s %-60s %16s %10.0f %8.0f\n' "$extrapolated" "$iterations" \
    "$energy" "$loop_s" "$(cat "$out.time")"
done
