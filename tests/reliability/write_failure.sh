#!/bin/sh
# Usage: write_failure.sh <ranks> <mpiexec> <build directory> <work dir>
# A write that fails (a full disk) stops the run with exit status 1 and a
# message naming the file, on every rank, without a hang or a backtrace
# (doc/willmore_flow.md, "Running it"). The failures are
# provoked without root: a symbolic link to /dev/full (every write fails
# with ENOSPC when flushed) in place of
#  - statistics.csv (its header);
#  - the VTU file of the last rank at step 1 (on 2 ranks only rank 1
#    fails: the other one must stop too, not wait for it);
#  - restored.png, the picture of edge_restoration;
# and a file size limit (ulimit -f, with SIGXFSZ ignored, so that writes
# fail with EFBIG) that statistics.csv reaches after a few rows: the run
# stops at that row and the file keeps only complete rows (this case on
# 1 rank only, in both variants).
mpiexec="$2"
ranks="$1"; build="$3"; work="$4"
. "$(dirname "$0")/common.sh"
rm -rf "$work"; mkdir -p "$work"
last_rank=$((ranks - 1))
willmore() {
  run "$ranks" "$build/willmore_flow" --set "Geometry/Shape=quarter circle" \
    --set "Mesh/Finest level=5" --set "Mesh/Coarsest level=3" \
    --set "Time stepping/Number of steps=2" "$@"
}

mkdir "$work/header"; ln -s /dev/full "$work/header/statistics.csv"
willmore --set "Output directory=$work/header"
expect "statistics.csv header" 1 \
  "Cannot write the file <$work/header/statistics.csv> \(No space left"

mkdir "$work/vtu"; ln -s /dev/full "$work/vtu/solution_00001.$last_rank.vtu"
willmore --set "Output directory=$work/vtu" --set "Output/VTU interval=1"
expect "VTU file of rank $last_rank" 1 \
  "Cannot write the file <$work/vtu/solution_00001.$last_rank.vtu>"
# step 1's row was written before its output, step 2 was not computed
rows=$(($(wc -l < "$work/vtu/statistics.csv") - 1))
[ "$rows" -eq 2 ] || { echo "FAIL: $rows rows instead of 2"; failed=1; }

mkdir "$work/picture"; ln -s /dev/full "$work/picture/restored.png"
run "$ranks" "$build/edge_restoration" --set "Mesh/Finest level=5" \
  --set "Time stepping/Number of steps=1" \
  --set "Output directory=$work/picture"
expect "picture" 1 "Cannot write the file <$work/picture/restored.png>"

# 1 KiB (bash's unit): the header and about four rows of statistics.csv;
# on 1 rank without mpirun, MPI kept off files larger than the limit
# (shared memory of the byte transfer layer and of PMIx's data store)
mkdir "$work/rows"
output=$(OMPI_MCA_btl=self PMIX_MCA_gds=hash OMP_NUM_THREADS=1 \
  timeout 60 bash -c 'trap "" XFSZ; ulimit -f 1;
  exec "$@"' sh "$build/willmore_flow" --set "Geometry/Shape=quarter circle" \
  --set "Mesh/Finest level=5" --set "Mesh/Coarsest level=3" \
  --set "Time stepping/Number of steps=20" --set "Output/VTU interval=0" \
  --set "Output directory=$work/rows" 2>&1)
status=$?
ranks=1
expect "statistics.csv row" 1 \
  "Cannot write the file <$work/rows/statistics.csv> \(File too large"
# every line complete: the same number of fields as the header
/usr/bin/python3 - "$work/rows/statistics.csv" <<'PY' || failed=1
import sys
lines = open(sys.argv[1]).read().split("\n")
n = len(lines[0].split(","))
bad = [l for l in lines[1:-1] if len(l.split(",")) != n] + lines[-1:] * (lines[-1] != "")
print(("FAIL: incomplete rows " + repr(bad)) if bad else
      f"OK: statistics.csv has {len(lines) - 2} complete rows and no partial one")
sys.exit(1 if bad else 0)
PY
exit $failed
