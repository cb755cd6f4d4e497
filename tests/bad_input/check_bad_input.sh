#!/bin/sh
# Usage: check_bad_input.sh <ranks> <mpiexec> <pattern> <program> [args...]
# Runs <program> [args...] on <ranks> ranks (1: without <mpiexec>) and
# passes if it exits with status 2 (the status of an input error, see
# run_program()), prints an error message matching <pattern> (grep -E)
# and neither deal.II's TimerOutput paragraph about an uncaught exception
# nor muParser's Message/Formula/Token block (the program's message is the
# only one), and neither crashes nor hangs (each run is limited to 60 s).
ranks="$1"; mpiexec="$2"; pattern="$3"; shift 3
time_limit=60
expected_status=2
if [ "$ranks" -eq 1 ]; then
  output=$(OMP_NUM_THREADS=1 timeout $time_limit "$@" 2>&1)
else
  output=$(OMP_NUM_THREADS=1 timeout $time_limit "$mpiexec" \
    --allow-run-as-root --oversubscribe -n "$ranks" "$@" 2>&1)
fi
status=$?
if [ $status -eq 124 ]; then
  echo "FAIL: timeout after $time_limit s on $ranks rank(s): $*"
  echo "$output"; exit 1
fi
if [ $status -ne $expected_status ]; then
  echo "FAIL: exit status $status (expected $expected_status) on $ranks" \
    "rank(s): $*"
  echo "$output"; exit 1
fi
if ! printf '%s' "$output" | grep -Eq "$pattern"; then
  echo "FAIL: message does not match <$pattern>:"; echo "$output"; exit 1
fi
if printf '%s' "$output" | grep -q "exception is currently uncaught"; then
  echo "FAIL: deal.II's TimerOutput paragraph about an uncaught exception:"
  echo "$output"; exit 1
fi
if printf '%s' "$output" | grep -Eq "^(Message|Formula|Token): +<"; then
  echo "FAIL: muParser's Message/Formula/Token block before the message:"
  echo "$output"; exit 1
fi
echo "OK: $* exits with status $status on $ranks rank(s) and the expected" \
  "message"
