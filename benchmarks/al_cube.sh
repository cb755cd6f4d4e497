#!/usr/bin/env bash
# The augmented Lagrangian in 3D (issue 13, thesis Table 7.3 setting):
# parameter_files/willmore_flow/al_cube_h<level>.prm (cube of edge 0.4,
# eps = 4h, tau = inner tau = h^2, iterative solver: multigrid product-form
# preconditioner), STEPS steps (default 1), no VTU output, 2 MPI ranks.
# Prints per step the outer (AL), trust-region and CG iterations, the
# Willmore energy and inside measure, and per run the wall time and the
# peak memory summed over the ranks (the program's own report).
# TYPE sets `Linear solver / Type` (default: the file's, auto).
# Usage: [STEPS=n] [TYPE=iterative|matrix-free]
#          benchmarks/al_cube.sh [build dir] [levels...]
#   e.g. benchmarks/al_cube.sh build 6
#        STEPS=10 benchmarks/al_cube.sh build 6 7
set -uo pipefail
build=${1:-build}; shift || true
levels=${*:-6}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for level in $levels; do
  out=$work/level_$level
  start=$(date +%s.%N)
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np 2 "$build/willmore_flow" \
    "parameter_files/willmore_flow/al_cube_h$level.prm" \
    --set "Output directory=$out" \
    --set "Time stepping/Number of steps=${STEPS:-1}" \
    --set "Linear solver/Type=${TYPE:-auto}" \
    --set "Output/VTU interval=0" > "$out.log" 2>&1 || echo "level $level: FAILED ($out.log)"
  end=$(date +%s.%N)
  echo "level $level: wall $(python3 -c "print(round($end - $start, 1))") s, $(grep "Peak resident memory" "$out.log")"
  printf '%5s %5s %6s %7s %12s %12s\n' step AL TR CG W inside
  /usr/bin/python3 - "$out/statistics.csv" <<'PY'
import csv, sys
for row in list(csv.DictReader(open(sys.argv[1])))[1:]:
    print(f'{row["step"]:>5} {row["al_iterations"]:>5} {row["tr_iterations"]:>6} '
          f'{row["linear_iterations"]:>7} {float(row["willmore_energy"]):>12.6g} '
          f'{float(row["inside_measure"]):>12.6g}')
PY
done
