#!/usr/bin/env bash
# Split (thesis Algorithm 6.1) against monolithic contour steps
# (`Time stepping / Contour coupling`, doc/shape_from_contour.md, "The
# monolithic coupling"): runs a contour parameter file twice on NP MPI
# ranks, with the split coupling and its own schedule, then with the
# monolithic coupling (MONO_STEPS as Steps per level, `Step size control`
# on unless CONTROL=false), one after the other, and prints per run the
# steps per level, all steps, the labeling error at the end of each level,
# the final j, W and total energy, the wall time; for the monolithic run
# also the first step (and its wall time) at which the labeling error on
# the last level is at most the split run's final one, and the same for the
# total energy (6.3) ("-" if never; the wall time in brackets); and
# for both the alternation of j: the share of the steps of each level's
# second half after which j changes its direction (rises after a fall or
# falls after a rise; a j that alternates from step to step gives 1, a
# monotone j 0).
# Usage: benchmarks/coupling_comparison.sh <file.prm> <output dir> [--set ...]
#   e.g. MONO_STEPS="50, 5, 3, 2" NP=1 benchmarks/coupling_comparison.sh \
#          parameter_files/shape_from_contour/fig6_5_disc.prm output/coupling_fig6_5
# Extra arguments are passed to both runs. Environment: NP = MPI ranks
# (default 2), MONO_STEPS (default: the file's), CONTROL (default true),
# BUILD (default build); ANALYSE_ONLY=1: no runs, only the table of the
# runs in <output dir>/split and <output dir>/monolithic.
set -euo pipefail
prm=$1; out=$2; shift 2
build=${BUILD:-build}
mkdir -p "$out"
printf '%-11s %-18s %5s %-34s %9s %8s %8s %7s %-14s %-14s %s\n' coupling "steps per level" \
  steps "labeling error at each level end" j W total wall_s "split's error" "split's total" alternation
for coupling in split monolithic; do
  extra=()
  if [ "$coupling" = monolithic ]; then
    extra=(--set "Time stepping/Step size control=${CONTROL:-true}")
    if [ -n "${MONO_STEPS:-}" ]; then
      extra+=(--set "Multilevel/Steps per level=$MONO_STEPS")
    fi
  fi
  if [ -z "${ANALYSE_ONLY:-}" ]; then
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np "${NP:-2}" "$build/shape_from_contour" "$prm" \
      "$@" "${extra[@]}" --set "Time stepping/Contour coupling=$coupling" \
      --set "Output directory=$out/$coupling" --set "Output/VTU interval=0" \
      > "$out/$coupling.log" 2>&1 || { echo "$coupling: FAILED, see $out/$coupling.log"; continue; }
  fi
  /usr/bin/python3 - "$out/$coupling/statistics.csv" "$coupling" "$out/split/statistics.csv" <<'PY'
import csv, os, sys
rows = list(csv.DictReader(open(sys.argv[1])))
levels, steps, errors, js = [], {}, {}, {}
for r in rows:
    level = int(float(r["level"]))
    if level not in levels:
        levels.append(level)
        steps[level], js[level] = 0, []
    else:
        # the first row of a level is its initial or transferred state
        steps[level] += 1
        js[level].append(float(r["mismatch_energy"]))
    errors[level] = float(r["labeling_error"])
turns = total = 0
for level in levels:
    j = js[level][len(js[level]) // 2:]
    for a, b, c in zip(j, j[1:], j[2:]):
        total += 1
        turns += (b - a) * (c - b) < 0
def first_reaching(name):
    # the first step on the last level with a value at most the split
    # run's final one
    target = float(list(csv.DictReader(open(split)))[-1][name])
    for r in rows[1:]:
        if int(float(r["level"])) == levels[-1] and float(r[name]) <= target:
            return f'{r["step"]} ({float(r["wall_seconds"]):.0f} s)'
    return "-"
reaches = energy = "-"
split = sys.argv[3]
if sys.argv[2] == "monolithic" and os.path.exists(split):
    reaches = first_reaching("labeling_error")
    energy = first_reaching("total_energy")
last = rows[-1]
print(f'{sys.argv[2]:<11} {", ".join(str(steps[l]) for l in levels):<18} '
      f'{sum(steps.values()):5d} {", ".join(f"{errors[l]:.3g}" for l in levels):<34} '
      f'{float(last["mismatch_energy"]):9.3g} {float(last["willmore_energy"]):8.4f} '
      f'{float(last["total_energy"]):8.5f} {float(last["wall_seconds"]):7.0f} '
      f'{reaches:<14} {energy:<14} {turns / max(total, 1):.2f}')
PY
done
