#!/usr/bin/env bash
# Fixed against automatic level transitions of shape_from_contour
# (doc/shape_from_contour.md, "Automatic against fixed level transitions"):
# runs a contour parameter file twice on NP MPI ranks, with its own
# `Multilevel / Transition` = fixed and with automatic (the same Steps per
# level as maxima), one after the other, and prints per run the steps per
# level, the labeling error at the end of each level, the final Willmore
# energy, total energy and inside measure, and the wall time.
# Usage: benchmarks/transition_comparison.sh <file.prm> <output dir> [--set ...]
#   e.g. benchmarks/transition_comparison.sh \
#          parameter_files/shape_from_contour/fig6_10_sphere.prm \
#          output/transition_sphere \
#          --set "Multilevel/Levels=5, 6" --set "Multilevel/Steps per level=99, 49"
# Extra arguments are passed to both runs. Environment: NP = MPI ranks
# (default 2); AUTO_STEPS = the automatic run's maximal steps per level
# (default: the same as the fixed run's), e.g. AUTO_STEPS="400, 100, 100".
set -euo pipefail
prm=$1; out=$2; shift 2
build=${BUILD:-build}
mkdir -p "$out"
printf '%-10s %-20s %6s %-36s %9s %9s %9s %8s\n' transition "steps per level" steps \
  "labeling error at each level end" W total inside wall_s
for transition in fixed automatic; do
  maxima=()
  if [ "$transition" = automatic ] && [ -n "${AUTO_STEPS:-}" ]; then
    maxima=(--set "Multilevel/Steps per level=$AUTO_STEPS")
  fi
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np "${NP:-2}" "$build/shape_from_contour" "$prm" \
    "$@" "${maxima[@]}" --set "Multilevel/Transition=$transition" \
    --set "Output directory=$out/$transition" --set "Output/VTU interval=0" \
    > "$out/$transition.log" 2>&1 || { echo "$transition: FAILED, see $out/$transition.log"; continue; }
  /usr/bin/python3 - "$out/$transition/statistics.csv" "$transition" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
levels, steps, errors = [], {}, {}
for r in rows:
    level = int(float(r["level"]))
    if level not in levels:
        levels.append(level)
        steps[level] = 0
    else:
        # the first row of a level is its initial or transferred state
        steps[level] += 1
    errors[level] = float(r["labeling_error"])
last = rows[-1]
print(f'{sys.argv[2]:<10} {", ".join(str(steps[l]) for l in levels):<20} '
      f'{sum(steps.values()):6d} {", ".join(f"{errors[l]:.3g}" for l in levels):<36} '
      f'{float(last["willmore_energy"]):9.4f} {float(last["total_energy"]):9.4f} '
      f'{float(last["inside_measure"]):9.5f} {float(last["wall_seconds"]):8.0f}')
PY
done
