#!/usr/bin/env bash
# Iterative 3D solver across levels (issue 14): the first STEPS steps
# (default 1) of the sphere (r = 0.35) and of the cube (edge 0.4) (or of
# the SHAPES given), eps = 4h, tau = 0.03h, inner tau = h^2, no output,
# NP MPI ranks (default 2). Prints per run the Newton and outer CG iterations summed
# over the steps, CG iterations per Newton iteration, the wall time of the
# run and the CPU time summed over the ranks, and below each row the
# program's line on how the final mesh is partitioned over the ranks.
# NP sets the number of ranks (default 2; more than the cores needs
# mpirun's --oversubscribe, which the script passes).
# Usage: [STEPS=n] [SHAPES="sphere cube"] [NP=n] benchmarks/solver_levels.sh
#          [build dir] [levels...]
#   e.g. benchmarks/solver_levels.sh build 5 6 7
#        STEPS=10 SHAPES=sphere benchmarks/solver_levels.sh build 7
#        NP=4 benchmarks/solver_levels.sh build 5 6 7   (partition on 4 ranks)
set -uo pipefail
build=${1:-build}; shift || true
levels=${*:-5 6}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-7s %-6s %6s %6s %8s %8s %8s\n' shape level newton cg cg/newton wall_s cpu_s
for level in $levels; do
  for shape in ${SHAPES:-sphere cube}; do
    size=$([ $shape = sphere ] && echo "Radius=0.35" || echo "Sizes=0.4")
    out=$work/${shape}_$level
    /usr/bin/time -f "%e %U" -o "$out.time" env OMP_NUM_THREADS=1 \
      mpirun --allow-run-as-root --oversubscribe -np "${NP:-2}" "$build/willmore_flow" \
      --set "Dimension=3" --set "Output directory=$out" \
      --set "Geometry/Shape=$shape" --set "Geometry/$size" \
      --set "Mesh/Finest level=$level" --set "Mesh/Coarsest level=3" \
      --set "Phase field/Epsilon=4*h" --set "Time stepping/Tau=0.03*h" \
      --set "Time stepping/Inner tau=h^2" \
      --set "Time stepping/Number of steps=${STEPS:-1}" \
      --set "Output/VTU interval=0" > "$out.log" 2>&1 || echo "$shape $level: FAILED ($out.log)"
    read -r wall cpu < "$out.time"
    /usr/bin/python3 - "$out/statistics.csv" "$shape" "$level" "$wall" "$cpu" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))[1:]
n = sum(int(float(row["newton_iterations"])) for row in rows)
cg = sum(int(float(row["linear_iterations"])) for row in rows)
print(f'{sys.argv[2]:<7} {sys.argv[3]:<6} {n:>6} {cg:>6} {cg / max(n, 1):>8.1f} {float(sys.argv[4]):>8.1f} {float(sys.argv[5]):>8.1f}')
PY
    grep "Partition of the final mesh" "$out.log" | sed 's/^/        /'
  done
done
