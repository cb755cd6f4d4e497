#!/usr/bin/env bash
# The two backends of the operator seam side by side (issue 50): the
# sphere (r = 0.35, or the cube of edge 0.4 with SHAPE=cube), eps = 4h,
# tau = 0.03h, inner tau = h^2, STEPS steps (default 2), no output, NP
# ranks (default 2), with `Linear solver / Type` = iterative (assembled L,
# CG + AMG) and matrix-free (CG + geometric multigrid). Prints per run the
# DoFs (3 fields), Newton and CG iterations, CG per Newton iteration, the
# wall time of the steps (statistics.csv), seconds per step and the peak
# resident memory summed over the ranks (the program's last lines) and the
# Willmore energy after the last step, and CG iterations per decade of
# residual reduction asked for (from the verbose Newton lines: the sum of
# the CG iterations over the sum of -log10 of the relative tolerances set
# by the Eisenstat-Walker forcing term), which does not depend on how
# tight Newton's method asked its systems to be solved, as CG per Newton
# iteration does. The runs are verbose (`Output / Verbose = true`) for
# this; the times include its output.
# SCHEME picks `Time stepping / Scheme` (default nested); EPS, TAU and
# INNER_TAU replace eps = 4*h, tau = 0.03*h and inner tau = h^2 (e.g.
# EPS=1/16 for one continuous problem on every level).
# Usage: [STEPS=n] [NP=n] [SHAPE=sphere|cube] [SCHEME=name]
#          [TYPES="iterative matrix-free"] [EPS=..] [TAU=..] [INNER_TAU=..]
#          benchmarks/matrix_free_comparison.sh [build dir] [levels...]
#   e.g. benchmarks/matrix_free_comparison.sh build 6 7
set -uo pipefail
build=${1:-build}; shift || true
levels=${*:-5 6}
shape=${SHAPE:-sphere}
size=$([ "$shape" = sphere ] && echo "Radius=0.35" || echo "Sizes=0.4")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-6s %-12s %10s %6s %6s %9s %9s %8s %8s %9s %12s\n' \
  level type dofs newton cg cg/newton cg/decade steps_s s/step memory_MB W
for level in $levels; do
  for type in ${TYPES:-iterative matrix-free}; do
    out=$work/${type}_$level
    env OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe \
      -np "${NP:-2}" "$build/willmore_flow" \
      --set "Dimension=3" --set "Output directory=$out" \
      --set "Geometry/Shape=$shape" --set "Geometry/$size" \
      --set "Mesh/Finest level=$level" --set "Mesh/Coarsest level=3" \
      --set "Phase field/Epsilon=${EPS:-4*h}" \
      --set "Time stepping/Tau=${TAU:-0.03*h}" \
      --set "Time stepping/Inner tau=${INNER_TAU:-h^2}" \
      --set "Time stepping/Number of steps=${STEPS:-2}" \
      --set "Time stepping/Scheme=${SCHEME:-nested}" \
      --set "Output/VTU interval=0" --set "Linear solver/Type=$type" \
      --set "Output/Verbose=true" \
      > "$out.log" 2>&1 || echo "$level $type: FAILED ($out.log)"
    memory=$(sed -n 's/.*Peak resident memory, summed over .* rank(s): \([0-9]*\) MiB.*/\1/p' "$out.log")
    /usr/bin/python3 - "$out/statistics.csv" "$level" "$type" "${memory:-0}" \
      "$out.log" <<'PY'
import csv, math, re, sys
rows = list(csv.DictReader(open(sys.argv[1])))
steps = rows[1:]
n = sum(int(float(r["newton_iterations"])) for r in steps)
cg = sum(int(float(r["linear_iterations"])) for r in steps)
wall = float(steps[-1]["wall_seconds"]) - float(rows[0]["wall_seconds"])
line = re.compile(r"Newton \d+: residual \S+ \((\d+) linear iterations "
                  r"to a relative (\S+),")
solves = [(int(m.group(1)), -math.log10(float(m.group(2))))
          for m in map(line.search, open(sys.argv[5])) if m]
decades = sum(d for _, d in solves)
per_decade = sum(i for i, _ in solves) / decades if decades > 0 else 0
print(f'{sys.argv[2]:<6} {sys.argv[3]:<12} {int(steps[-1]["dofs"]):>10} {n:>6} {cg:>6} '
      f'{cg / max(n, 1):>9.1f} {per_decade:>9.2f} {wall:>8.1f} {wall / len(steps):>8.1f} {sys.argv[4]:>9} '
      f'{float(steps[-1]["willmore_energy"]):>12.8f}')
PY
  done
done
