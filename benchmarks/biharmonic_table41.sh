#!/usr/bin/env bash
# Thesis Table 4.1 study (Dirichlet, Lemma 4.5): the four tau/ttau
# combinations of parameter_files/biharmonic_flow/table41_*.prm on the given
# levels, biharmonic_flow with 2 MPI ranks (one factorisation per mesh).
# Prints, per combination, the wall time and the EOCs of L2 and H1 error for
# each transition level -> next level, then the total wall time.
# Usage: benchmarks/biharmonic_table41.sh [build dir] [levels] [ranks]
#   e.g. benchmarks/biharmonic_table41.sh build 5,6,7,8 2
set -euo pipefail
build=${1:-build}
levels=${2:-5,6,7,8}
ranks=${3:-2}
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "biharmonic_flow Table 4.1 study, levels $levels, $ranks MPI rank(s), $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ)"
printf '%-26s %8s  %s\n' case wall_s "EOC L2/H1 per transition k -> k+1"
total_start=$(date +%s.%N)
for case in table41_tau_h2_ttau_h2 table41_tau_h2_ttau_h table41_tau_h_ttau_h2 table41_tau_h_ttau_h; do
  prm=$work/$case.prm
  # later `set` lines override the ones in the file
  cat "$here/parameter_files/biharmonic_flow/$case.prm" > "$prm"
  printf 'set Output directory = %s\nsubsection Convergence\n  set Levels = %s\nend\n' \
    "$work/$case" "$levels" >> "$prm"
  start=$(date +%s.%N)
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np "$ranks" "$build/biharmonic_flow" "$prm" > "$work/$case.log" 2>&1 ||
    { echo "$case failed:"; cat "$work/$case.log"; exit 1; }
  end=$(date +%s.%N)
  /usr/bin/python3 - "$work/$case/convergence.csv" "$case" "$start" "$end" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
eocs = []
for a, b in zip(rows, rows[1:]):
    dl = math.log(float(a["h"]) / float(b["h"]))
    l2 = math.log(float(a["l2_error"]) / float(b["l2_error"])) / dl
    h1 = math.log(float(a["h1_error"]) / float(b["h1_error"])) / dl
    eocs.append(f'k={int(float(a["level"]))}: {l2:.3f}/{h1:.3f}')
print(f'{sys.argv[2]:<26} {float(sys.argv[4]) - float(sys.argv[3]):8.1f}  ' + '  '.join(eocs))
PY
done
total_end=$(date +%s.%N)
/usr/bin/python3 -c "import sys; print(f'total wall time {float(sys.argv[2]) - float(sys.argv[1]):.1f} s')" "$total_start" "$total_end"
