#!/usr/bin/env bash
# 2D vesicle equilibria (doc/vesicles.md, "Results in 2D"): the
# shipped parameter_files/vesicles/ellipse_nu<NN>_2d.prm at each finest
# level (eps = 4h as in the files), run to stationarity on 2 MPI ranks
# without VTU output. Prints one row per run: reduced area, level, steps,
# Newton iterations (sum), e = W L / (2 pi^2) at the end (L: the area
# functional), its difference to the sharp-interface value, the largest
# relative drift of the held area and length over the steps, wall seconds.
# Usage: [TOLERANCE=1e-2] benchmarks/vesicles_2d.sh [build dir] [levels...]
#   e.g. benchmarks/vesicles_2d.sh build 7 8 9
set -euo pipefail
build=${1:-build}; shift || true
levels=${*:-7 8 9}
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# sharp-interface references (axisymmetric shooting; issue 70)
declare -A sharp=([07]=1.986839 [05]=2.767871)
printf '%-4s %-5s %6s %7s %9s %8s %9s %8s\n' nu level steps newton e vs_sharp drift wall_s
for nu in 07 05; do
  for level in $levels; do
    settings=(--set "Mesh/Finest level=$level" --set "Output/VTU interval=0"
              --set "Output directory=$work/out")
    [ -n "${TOLERANCE:-}" ] && settings+=(--set "Time stepping/Tolerance=$TOLERANCE")
    rm -rf "$work/out"
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np 2 "$build/willmore_flow" \
      "$here/parameter_files/vesicles/ellipse_nu${nu}_2d.prm" \
      "${settings[@]}" > "$work/log" 2>&1
    /usr/bin/python3 - "$work/out/statistics.csv" "$nu" "$level" "${sharp[$nu]}" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))[1:]
last = rows[-1]
e = float(last["willmore_energy"]) * float(last["area_energy"]) / (2 * math.pi**2)
sharp = float(sys.argv[4])
drift = max(max(abs(float(r["volume_change"])), abs(float(r["area_change"])))
            for r in rows)
print("0.%s  %-5s %6d %7d %9.4f %+7.2f%% %9.1e %8.1f" % (
    sys.argv[2][1], sys.argv[3], len(rows),
    sum(float(r["newton_iterations"]) for r in rows), e,
    100 * (e - sharp) / sharp, drift, float(last["wall_seconds"])))
PY
  done
done
