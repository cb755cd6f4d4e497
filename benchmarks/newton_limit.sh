#!/usr/bin/env bash
# The default of `Newton / Maximum iterations` (issue 14): runs shipped
# cases with each limit of LIMITS (default "15 30") and prints per run the
# Newton iterations summed over the steps (descent iterations included),
# how often the descent method took over after a failed Newton solve, the
# step halvings, the final Willmore energy and the wall time.
# Cases (CASES, default "square demo disc cube6"):
#   square  the square of tests/newton_descent_fallback.cc (2D, level 6,
#           tau = 0.1h, 1 step): a first step from sharp corners
#   demo    willmore_flow's built-in default (two_circles_demo.prm)
#   disc    shape_from_contour fig6_5_disc.prm
#   cube6   parameter_files/willmore_flow/cube.prm (3D, level 6)
#   cube7   the same at Finest level = 7 (5-12 min per run)
# NP MPI ranks (default 2), no VTU output.
# Usage: [LIMITS="15 30"] [CASES="..."] [NP=n] benchmarks/newton_limit.sh
#          [build dir]
set -uo pipefail
build=${1:-build}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
prm=$source_dir/parameter_files
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# sets `command` to the program and arguments of case $1
set_command() {
  case $1 in
    square) command=(willmore_flow --set "Geometry/Shape=cube"
                     --set "Geometry/Sizes=0.4" --set "Mesh/Finest level=6"
                     --set "Time stepping/Tau=0.1*h"
                     --set "Time stepping/Number of steps=1") ;;
    demo) command=(willmore_flow "$prm/willmore_flow/two_circles_demo.prm") ;;
    disc) command=(shape_from_contour "$prm/shape_from_contour/fig6_5_disc.prm") ;;
    cube6) command=(willmore_flow "$prm/willmore_flow/cube.prm") ;;
    cube7) command=(willmore_flow "$prm/willmore_flow/cube.prm"
                    --set "Mesh/Finest level=7") ;;
    *) echo "unknown case $1" >&2; exit 2 ;;
  esac
}

printf '%-7s %5s %7s %8s %9s %12s %8s\n' case limit newton descent halvings final_W wall_s
for name in ${CASES:-square demo disc cube6}; do
  for limit in ${LIMITS:-15 30}; do
    set_command "$name"
    out=$work/${name}_$limit
    /usr/bin/time -f "%e" -o "$out.time" env OMP_NUM_THREADS=1 \
      mpirun --allow-run-as-root --oversubscribe -np "${NP:-2}" \
      "$build/${command[0]}" "${command[@]:1}" \
      --set "Newton/Maximum iterations=$limit" \
      --set "Output/VTU interval=0" --set "Output directory=$out" \
      > "$out.log" 2>&1 || echo "$name $limit: FAILED ($out.log)"
    descent=$(grep -c "the descent method from the start" "$out.log")
    /usr/bin/python3 - "$out/statistics.csv" "$name" "$limit" "$descent" \
      "$(cat "$out.time")" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
newton = sum(int(float(r["newton_iterations"])) for r in rows[1:])
halvings = sum(int(float(r["step_halvings"])) for r in rows[1:])
print(f'{sys.argv[2]:<7} {sys.argv[3]:>5} {newton:>7} {sys.argv[4]:>8} '
      f'{halvings:>9} {float(rows[-1]["willmore_energy"]):>12.7g} '
      f'{float(sys.argv[5]):>8.1f}')
PY
  done
done
