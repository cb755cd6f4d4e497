#!/usr/bin/env bash
# Robustness study of thesis section 5.2.3: both schemes on the quarter
# circle at h = 2^-7 (eps = 2^-6) for 10 steps with large time steps, no
# step halving, at most 50 Newton iterations per step. Prints, per run, the
# Newton iterations of every completed step and how the run ended.
# Usage: benchmarks/robustness.sh [build dir] [output dir] [tau expressions...]
#   e.g. benchmarks/robustness.sh build output/robustness 0.03*h 0.1*h 0.3*h
set -uo pipefail
build=${1:-build}; shift || true
out=${1:-output/robustness}; shift || true
taus=${*:-0.03*h 0.1*h 0.3*h}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
printf '%-8s %-13s %-9s %-44s %s\n' tau scheme result "newton iterations per step" "final W"
for tau in $taus; do
  for scheme in nested semi_implicit; do
    name=${scheme}_${tau//[*^]/_}
    sed -e "s|set Output directory = .*|set Output directory = $out/$name|" \
        -e "s|set Tau             = .*|set Tau             = $tau|" \
        -e "s|set VTU interval = 5|set VTU interval = 0|" \
        "$here/parameter_files/willmore_flow/robustness_$scheme.prm" > "$out/$name.prm"
    if OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np 2 "$build/willmore_flow" "$out/$name.prm" \
         > "$out/$name.log" 2>&1; then result=converged; else result=FAILED; fi
    /usr/bin/python3 - "$out/$name/statistics.csv" "$tau" "$scheme" "$result" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
its = " ".join(str(int(float(r["newton_iterations"]))) for r in rows[1:])
print(f'{sys.argv[2]:<8} {sys.argv[3]:<13} {sys.argv[4]:<9} {its:<44} {float(rows[-1]["willmore_energy"]):.4f}')
PY
    [ "$result" = FAILED ] && grep -A3 "error:" "$out/$name.log" | sed 's/^/    /' | head -4
  done
done
