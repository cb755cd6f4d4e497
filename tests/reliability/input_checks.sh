#!/bin/sh
# Usage: input_checks.sh <ranks> <mpiexec> <build directory> <work directory>
# Inputs that cannot be kept as files of the source tree, or that need a
# run first (doc/willmore_flow.md, "Input checks"):
# - included parameter files that are a FIFO or larger than 16 MiB: exit 2
#   naming the file, never read (a FIFO without a writer would block);
# - a parameter file that starts with a UTF-8 byte order mark runs;
# - an expression of 400 kB: exit 2, the message and the log's echo of
#   the parameters quote 200 characters;
# - Epsilon = 0.75 h runs with a warning about the resolution;
# - a uniform 2D mesh at level 10 (about 8.6 GB) under `ulimit -v` of 4 GB:
#   exit 2 with the estimate and the memory per rank;
# - shape_from_contour resumed after the last step of its last level:
#   exit 2, no step to take (as willmore_flow).
ranks="$1"; mpiexec="$2"; build="$3"; work="$4"
. "$(dirname "$0")/common.sh"
source_tests=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$work"; mkdir -p "$work"
flow="$build/willmore_flow"
small() {
  run "$ranks" "$flow" "$@" --set "Mesh/Finest level=5" \
    --set "Time stepping/Number of steps=1" --set "Output/VTU interval=0" \
    --set "Output directory=$work/run"
}

mkfifo "$work/fifo"
printf 'include %s\n' "$work/fifo" > "$work/include_fifo.prm"
small "$work/include_fifo.prm"
expect "include of a FIFO" 2 \
  "parameter file <$work/fifo> .included by <$work/include_fifo.prm>. is not a regular file"

truncate -s 17M "$work/huge.prm"
printf 'include %s\n' "$work/huge.prm" > "$work/include_huge.prm"
small "$work/include_huge.prm"
expect "include of a 17 MiB file" 2 \
  "parameter file <$work/huge.prm> .included by <$work/include_huge.prm>. is larger than 16 MiB"

printf '\357\273\277set Dimension = 2\n' > "$work/bom.prm"
small "$work/bom.prm"
expect "a byte order mark before line 1" 0 "Peak resident memory"

# a parameter file: an argument of 400 kB is more than execve() takes
/usr/bin/python3 -c "print('subsection Geometry\n  set Shape = function\n'
  '  set Expression = ' + '0*x+' * 100000 + 'sqrt(x^2+y^2)-0.25+\nend')" \
  > "$work/long_expression.prm"
small "$work/long_expression.prm"
expect "an expression of 400 kB" 2 \
  "<Geometry / Expression> = <(0\\*x\\+){50}\\.\\.\\. \\(400[0-9]{3} characters\\)>"
message=$(printf '%s\n' "$output" | grep "input error")
[ ${#message} -gt 1000 ] && {
  echo "FAIL: the message about the long expression has ${#message} characters"
  failed=1; }
# nor does the log's echo of the parameters quote it in full
longest=$(printf '%s\n' "$output" | awk '{ if (length($0) > m) m = length($0) } END { print m + 0 }')
[ "$longest" -gt 1000 ] && {
  echo "FAIL: the log of the long expression has a line of $longest characters"
  failed=1; }

# a circle, and Inner tau below eps^2/2 (the demo's inner problem fails)
small --set "Phase field/Epsilon=0.75*h" --set "Geometry/Shape=circle" \
  --set "Time stepping/Inner tau=0.1*h^2"
expect "Epsilon = 0.75 h" 0 \
  "Warning: <Phase field / Epsilon> = 0.0234 is 0.75 h at h = 0.031[0-9]*: the mesh hardly resolves the interface"

output=$(ulimit -v 4000000; OMP_NUM_THREADS=1 timeout 60 sh -c '
  if [ "$1" -eq 1 ]; then shift 2; exec "$@"; fi
  exec "$2" --allow-run-as-root --oversubscribe -n "$1" "$3" "$4" "$5" "$6"' \
  run "$ranks" "$mpiexec" "$flow" "$source_tests/bad_input/uniform_2d_level_12.prm" \
  --set "Mesh/Finest level=10" 2>&1)
status=$?
expect "uniform level 10 under ulimit -v 4 GB" 2 \
  "uniform mesh of 1048576 cells .* about (9|5) GB per rank at 8 KB per cell.; this machine has about [0-4] GB per rank"

contour() {
  run "$ranks" "$build/shape_from_contour" --set "Multilevel/Levels=5" \
    --set "Multilevel/Steps per level=2" --set "Checkpoint/Interval=1" \
    --set "Output/VTU interval=0" --set "Output directory=$work/contour" "$@"
}
contour
expect "shape_from_contour, 2 steps with checkpoints" 0 "checkpoint written after step 2"
contour --set "Checkpoint/Resume=true"
expect "shape_from_contour resumed after its last step" 2 \
  "is after step 2, and this run ends with step 2.*no step to take"
exit $failed
