#!/bin/sh
# Usage: checkpoint_file_size_limit.sh <ranks> <mpiexec> <willmore_flow>
#                                      <work directory>
# A checkpoint that a file size limit would cut short is never written as
# complete (doc/willmore_flow.md, "Checkpoint and resume"). A run of 2
# steps (quarter circle at level 5, checkpoint every 2 steps) writes
# checkpoint-2; a resume to step 4 under a file size limit below the size
# of its mesh_fixed.data (ulimit -f, SIGXFSZ ignored, as a filling quota
# behaves) must exit with status 1 naming the checkpoint file and the
# limit, leave checkpoint-2 as it was (same checksums) and no other
# checkpoint; a resume without the limit then continues from checkpoint-2
# to step 4 with exit status 0.
ranks="$1"; mpiexec="$2"; program="$3"; work="$4"
. "$(dirname "$0")/common.sh"
rm -rf "$work"; mkdir -p "$work"
# willmore <runner> <args...>: the run of this test by <runner>
willmore() {
  runner="$1"; shift
  "$runner" "$program" --set "Geometry/Shape=quarter circle" \
    --set "Mesh/Finest level=5" --set "Mesh/Coarsest level=3" \
    --set "Output/VTU interval=0" --set "Checkpoint/Interval=2" \
    --set "Output directory=$work/run" "$@"
}
normal() { run "$ranks" "$@"; }
# under the file size limit $limit (KiB, bash's unit) with SIGXFSZ
# ignored; MPI keeps its own files (shared memory of the byte transfer
# layer, PMIx's data store) below the limit with these settings
limited() {
  if [ "$ranks" -eq 1 ]; then
    set -- env OMPI_MCA_btl=self "$@"
  else
    set -- env OMPI_MCA_btl=tcp,self "$mpiexec" --allow-run-as-root \
      --oversubscribe -n "$ranks" "$@"
  fi
  output=$(PMIX_MCA_gds=hash OMP_NUM_THREADS=1 timeout 60 bash -c \
    'limit="$1"; shift; trap "" XFSZ; ulimit -f "$limit"; exec "$@"' \
    sh "$limit" "$@" 2>&1)
  status=$?
}
willmore normal --set "Time stepping/Number of steps=2"
expect "the run that writes checkpoint-2" 0 "checkpoint written after step 2"
metadata="$work/run/checkpoint-2/checkpoint.txt"
cp "$metadata" "$work/checkpoint-2.txt"
# 1 KiB below the size of mesh_fixed.data
size=$(wc -c < "$work/run/checkpoint-2/mesh_fixed.data")
limit=$((size / 1024 - 1))
echo "mesh_fixed.data: $size bytes; file size limit $limit KiB"
willmore limited --set "Checkpoint/Resume=true" \
  --set "Time stepping/Number of steps=4"
expect "checkpoint-4 under a file size limit of $limit KiB" 1 \
  "Cannot write the checkpoint file <$work/run/checkpoint-4.tmp/mesh(_fixed.data)?>: it needs [0-9]+ bytes, more than the file size limit of this process \($((limit * 1024)) bytes"
left=$(cd "$work/run" && ls -d checkpoint-* | tr '\n' ' ')
if [ "$left" != "checkpoint-2 " ]; then
  echo "FAIL: checkpoints left: <$left>, expected <checkpoint-2 >"; failed=1
fi
if ! cmp -s "$metadata" "$work/checkpoint-2.txt"; then
  echo "FAIL: checkpoint-2/checkpoint.txt changed"; failed=1
fi
willmore normal --set "Checkpoint/Resume=true" \
  --set "Time stepping/Number of steps=4"
expect "resume from checkpoint-2 without the limit" 0 \
  "checkpoint written after step 4"
exit $failed
