#!/usr/bin/env bash
# Quarter-circle benchmark (thesis Table 5.1 setting): adaptive vs uniform
# mesh at the given levels, nested scheme, 2 MPI ranks. Prints one table row
# per run: level, mesh, cells, steps, mean/max Newton iterations, final
# l2_error, radius error from inside_measure, wall seconds.
# Usage: [MESHES="adaptive uniform"] benchmarks/quarter_circle.sh [build dir] [levels...]
#   e.g. benchmarks/quarter_circle.sh build 7 8 9
# MESHES (default "adaptive uniform") selects the meshes; uniform is never
# run at level 9 and above. MARGIN, INTERVAL and VTU, if set, override
# Mesh / Band margin, Mesh / Refinement interval and Output / VTU interval
# of the files (VTU output then goes to a temporary directory), e.g.
#   MARGIN=0 INTERVAL=1 VTU=5 MESHES=adaptive benchmarks/quarter_circle.sh build 9
set -euo pipefail
build=${1:-build}; shift || true
levels=${*:-7 8}
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
printf '%-5s %-8s %8s %5s %7s %4s %12s %12s %8s\n' level mesh cells steps newton max l2_error radius_err wall_s
for level in $levels; do
  for mesh in ${MESHES:-adaptive uniform}; do
    adaptive=$([ "$mesh" = uniform ] && echo false || echo true)
    [ "$adaptive" = false ] && [ "$level" -ge 9 ] && continue
    prm=$work/qc_${level}_${adaptive}.prm
    sed -e "s|set Output directory = .*|set Output directory = $work/out_${level}_${adaptive}|" \
        -e "s|set Adaptive            = true|set Adaptive            = $adaptive|" \
        -e "s|set VTU interval = 20|set VTU interval = 0|" \
        "$here/parameter_files/willmore_flow/quarter_circle_h$level.prm" > "$prm"
    overrides=()
    [ -n "${MARGIN:-}" ] && overrides+=(--set "Mesh/Band margin=$MARGIN")
    [ -n "${INTERVAL:-}" ] && overrides+=(--set "Mesh/Refinement interval=$INTERVAL")
    [ -n "${VTU:-}" ] && overrides+=(--set "Output/VTU interval=$VTU")
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np 2 "$build/willmore_flow" "$prm" "${overrides[@]}" > "$work/log_${level}_${adaptive}" 2>&1
    /usr/bin/python3 - "$work/out_${level}_${adaptive}/statistics.csv" "$level" "$adaptive" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
n = [float(r["newton_iterations"]) for r in rows[1:]]
last = rows[-1]
t = float(last["time"])
r_exact = (2 * t + 0.4 ** 4) ** 0.25
r = math.sqrt(4 * float(last["inside_measure"]) / math.pi)
print(f'{sys.argv[2]:<5} {"adaptive" if sys.argv[3] == "true" else "uniform":<8} '
      f'{float(last["cells"]):8.0f} {len(rows) - 1:5d} {sum(n) / len(n):7.2f} {max(n):4.0f} '
      f'{float(last["l2_error"]):12.5e} {r / r_exact - 1:12.3e} {float(last["wall_seconds"]):8.1f}')
PY
  done
done
rm -rf "$work"
