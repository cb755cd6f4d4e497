#!/bin/sh
# Usage: checkpoint_verification.sh <ranks> <mpiexec> <willmore_flow>
#                                   <work directory>
# A resume verifies the checkpoint before anything reads it
# (doc/willmore_flow.md, "Checkpoint and resume"). A run of 2 steps
# (quarter circle at level 5, checkpoint after step 2) is resumed up to
# step 3 from copies of its output directory with one thing wrong each; each
# must exit with status 2 and a message naming the file or the parameter:
# a truncated, a changed (same size), an empty and a missing mesh file, a
# checkpoint.txt without its header, a state.txt with a time later than
# the steps reach, a negative step size or a step before its step offset
# (with checksums that match), another Finest level, Epsilon or
# Dimension, a statistics.csv without the checkpoint's row and with
# damaged rows (a bad step, letters, too few entries), an unknown name in
# <Checkpoint / Allow parameter change>, and Number of steps = the
# checkpoint's step. On 2 ranks only the truncated file, the Finest level,
# the short statistics.csv, the row with letters and the unknown name of
# these (the others are checked by the same code on rank 0). Then an
# allowed change (<Checkpoint / Allow parameter change>) resumes with a
# warning, and the untouched copy resumes. Also the output directory lock:
# a lock of a running process refuses the run (exit 2, naming the pid),
# a stale one (a process that ended) is reported and replaced, and no lock
# file is left after a run.
ranks="$1"; mpiexec="$2"; program="$3"; work="$4"
. "$(dirname "$0")/common.sh"
rm -rf "$work"; mkdir -p "$work"
base() {
  dir="$1"; shift
  run "$ranks" "$program" --set "Geometry/Shape=quarter circle" \
    --set "Mesh/Finest level=5" --set "Mesh/Coarsest level=3" \
    --set "Output/VTU interval=0" --set "Checkpoint/Interval=2" \
    --set "Output directory=$work/$dir" "$@"
}
base original --set "Time stepping/Number of steps=2"
expect "the run that writes the checkpoint" 0 "checkpoint written after step 2"
checkpoint=checkpoint-2
# copy <name>: a copy of the original output directory
copy() { cp -r "$work/original" "$work/$1"; }
resume() { dir="$1"; shift
  base "$dir" --set "Checkpoint/Resume=true" \
    --set "Time stepping/Number of steps=3" "$@"; }

copy truncated
size=$(wc -c < "$work/truncated/$checkpoint/mesh_fixed.data")
truncate -s $((size / 2)) "$work/truncated/$checkpoint/mesh_fixed.data"
resume truncated
expect "truncated mesh_fixed.data" 2 \
  "checkpoint file <$work/truncated/$checkpoint/mesh_fixed.data> has [0-9]+ bytes instead of $size \(truncated\)"

if [ "$ranks" -eq 1 ]; then
  copy changed
  printf 'XXXX' | dd of="$work/changed/$checkpoint/mesh_fixed.data" bs=1 \
    seek=100 conv=notrunc 2>/dev/null
  resume changed
  expect "changed mesh_fixed.data" 2 \
    "<$work/changed/$checkpoint/mesh_fixed.data> does not have the checksum"
fi

# edit <name> <line> <replacement>: replace the line starting with <line>
# of state.txt in the copy <name> and record its new size and checksum
# in checkpoint.txt (64-bit FNV-1a), as a consistent but wrong checkpoint
edit() {
  copy "$1"
  /usr/bin/python3 - "$work/$1/$checkpoint" "$2" "$3" <<'PY'
import os, sys
directory, key, replacement = sys.argv[1:]
state = os.path.join(directory, "state.txt")
lines = open(state).read().split("\n")
lines = [replacement if l.startswith(key + " ") else l for l in lines]
data = "\n".join(lines).encode()
open(state, "wb").write(data)
h = 14695981039346656037
for b in data:
    h = ((h ^ b) * 1099511628211) % 2**64
meta = os.path.join(directory, "checkpoint.txt")
out = [f"file state.txt {len(data)} {h:016x}" if l.startswith("file state.txt ")
       else l for l in open(meta).read().split("\n")]
open(meta, "w").write("\n".join(out))
PY
}

# the other damaged files are checked by the same code on rank 0: on 2
# ranks the truncated file above shows that every rank stops
if [ "$ranks" -eq 1 ]; then
  copy empty; : > "$work/empty/$checkpoint/mesh"
  resume empty
  expect "empty mesh file" 2 "<$work/empty/$checkpoint/mesh> has 0 bytes"

  copy missing; rm "$work/missing/$checkpoint/mesh.info"
  resume missing
  expect "missing mesh.info" 2 "<$work/missing/$checkpoint/mesh.info> is missing"

  copy metadata; echo "something else" > "$work/metadata/$checkpoint/checkpoint.txt"
  resume metadata
  expect "damaged checkpoint.txt" 2 \
    "<$work/metadata/$checkpoint/checkpoint.txt> is missing or damaged"

  edit late time "time 1e10"
  resume late
  expect "state.txt: a time later than the steps reach" 2 \
    "checkpoint <$work/late/$checkpoint> is after step 2 at time 10000000000.*later than"
  edit negative state_tau "state_tau -0.001"
  resume negative
  expect "state.txt: a negative step size" 2 \
    "checkpoint file <$work/negative/$checkpoint/state.txt> is damaged: the step size -0.001000 is not a positive number"
  edit offset step_offset "step_offset 5"
  resume offset
  expect "state.txt: a step before the step offset" 2 \
    "state.txt> is damaged: step 2 is before the step offset 5"
fi

copy level; resume level --set "Mesh/Finest level=6"
expect "another Finest level" 2 \
  "<Mesh / Finest level> = 5 in the checkpoint .*but 6 in this run"

if [ "$ranks" -eq 1 ]; then
  copy epsilon; resume epsilon --set "Phase field/Epsilon=3*h"
  expect "another Epsilon" 2 "<Phase field / Epsilon> = 0.125 in the checkpoint"

  copy dimension; resume dimension --set "Dimension=3" --set "Geometry/Shape=sphere"
  expect "another Dimension" 2 "<Dimension> = 2 in the checkpoint .*but 3"
fi

copy short; sed -i '$d' "$work/short/statistics.csv"
resume short
expect "statistics.csv without the checkpoint's row" 2 \
  "Cannot continue <$work/short/statistics.csv>: it has no row of step 2"

if [ "$ranks" -eq 1 ]; then
  copy badrow; sed -i '3s/^1,/x,/' "$work/badrow/statistics.csv"
  resume badrow
  expect "damaged statistics.csv row" 2 \
    "Cannot continue <$work/badrow/statistics.csv>: line 3 <x,"
fi

# whole rows are checked, not only their step
copy letters; sed -i '3s/^1,[^,]*,/1,abc,/' "$work/letters/statistics.csv"
resume letters
expect "statistics.csv row with letters" 2 \
  "Cannot continue <$work/letters/statistics.csv>: line 3 <1,abc,.*> has <abc> in column 2, which is not a number"

if [ "$ranks" -eq 1 ]; then
  copy short_row; sed -i '3s/.*/nan,inf/' "$work/short_row/statistics.csv"
  resume short_row
  expect "statistics.csv row nan,inf" 2 \
    "Cannot continue <$work/short_row/statistics.csv>: line 3 <nan,inf> has 2 entries instead of [0-9]+"
fi

copy bogus; resume bogus --set "Checkpoint/Allow parameter change=Bogus / Name"
expect "Allow parameter change of an unknown name" 2 \
  "<Checkpoint / Allow parameter change> names <Bogus / Name>, which is not a parameter that this run's checkpoints record; they record: .*Phase field / Epsilon"

copy nothing; resume nothing --set "Time stepping/Number of steps=2"
expect "no step after the checkpoint" 2 \
  "is after step 2, and this run ends with step 2.*no step to take"

copy allowed
resume allowed --set "Phase field/Epsilon=3*h" \
  --set "Checkpoint/Allow parameter change=Phase field/Epsilon"
expect "allowed change of Epsilon" 0 \
  "Warning: resuming with <Phase field / Epsilon> = 0.125 in the checkpoint"

copy intact; resume intact
expect "intact checkpoint" 0 "resuming after step 2"
[ -e "$work/intact/phasefield.lock" ] &&
  { echo "FAIL: the lock file is left after the run"; failed=1; }

# a lock of a running process (this script's shell) on this host
copy locked
printf 'pid %s\nhost %s\n' $$ "$(hostname)" > "$work/locked/phasefield.lock"
resume locked
expect "locked output directory" 2 \
  "output directory <$work/locked> is in use by process $$ on host"

# a stale lock: a process that has ended
copy stale
sh -c 'exit 0' & dead=$!; wait $dead
printf 'pid %s\nhost %s\n' $dead "$(hostname)" > "$work/stale/phasefield.lock"
resume stale
expect "stale lock" 0 "locked by process $dead on this host, which no longer runs"
exit $failed
