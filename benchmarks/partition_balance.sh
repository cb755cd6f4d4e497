#!/usr/bin/env bash
# Partition balance of the 3D narrow band (issue 14, doc/scaling.md): one
# step of the sphere (r = 0.35) and of the cube (edge 0.4) (or of the
# SHAPES given), eps = 4h, tau = 0.03h, inner tau = h^2, no output, on NP
# MPI ranks (default 2). Prints per run the DoFs (3 fields) and the
# fewest and most locally owned cells and DoFs (one field) of any rank, as the
# program's line "Partition of the final mesh" reports them, and the
# largest share of a rank relative to the mean.
# Usage: [NP=n] [SHAPES="sphere cube"] benchmarks/partition_balance.sh
#          [build dir] [levels...]
#   e.g. NP=4 benchmarks/partition_balance.sh build 5 6 7
set -uo pipefail
build=${1:-build}; shift || true
levels=${*:-5 6}
np=${NP:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-7s %-6s %5s %10s %21s %21s %7s\n' shape level ranks dofs cells/rank dofs/rank largest
for level in $levels; do
  for shape in ${SHAPES:-sphere cube}; do
    size=$([ $shape = sphere ] && echo "Radius=0.35" || echo "Sizes=0.4")
    out=$work/${shape}_$level
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$np" \
      "$build/willmore_flow" \
      --set "Dimension=3" --set "Output directory=$out" \
      --set "Geometry/Shape=$shape" --set "Geometry/$size" \
      --set "Mesh/Finest level=$level" --set "Mesh/Coarsest level=3" \
      --set "Phase field/Epsilon=4*h" --set "Time stepping/Tau=0.03*h" \
      --set "Time stepping/Inner tau=h^2" \
      --set "Time stepping/Number of steps=1" \
      --set "Output/VTU interval=0" > "$out.log" 2>&1 ||
      { echo "$shape $level: FAILED"; tail -n 5 "$out.log"; continue; }
    line=$(grep "Partition of the final mesh" "$out.log")
    dofs=$(python3 -c "import csv, sys; print(int(float(list(csv.DictReader(open(sys.argv[1])))[-1]['dofs'])))" "$out/statistics.csv")
    echo "$line" | sed -E 's/.*: ([0-9]+)-([0-9]+) cells and ([0-9]+)-([0-9]+) DoFs.*share ([0-9.]+) x.*/\1 \2 \3 \4 \5/' |
      { read c0 c1 d0 d1 share
        printf '%-7s %-6s %5s %10s %21s %21s %7s\n' "$shape" "$level" "$np" "$dofs" "$c0-$c1" "$d0-$d1" "$share"; }
  done
done
