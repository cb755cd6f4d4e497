# Helpers of the reliability tests (sourced; needs $mpiexec).
# run <ranks> <command...>: runs the command on <ranks> MPI ranks (1:
# without mpiexec) for at most $time_limit s (default 60); sets $status
# and $output.
time_limit=60
run() {
  ranks="$1"; shift
  if [ "$ranks" -eq 1 ]; then
    output=$(OMP_NUM_THREADS=1 timeout $time_limit "$@" 2>&1)
  else
    output=$(OMP_NUM_THREADS=1 timeout $time_limit "$mpiexec" \
      --allow-run-as-root --oversubscribe -n "$ranks" "$@" 2>&1)
  fi
  status=$?
}

# expect <case> <status> <pattern>: the last run() exited with <status>
# (not by a timeout), printed a message matching <pattern> (grep -E), no
# backtrace and no paragraph of deal.II's TimerOutput about an uncaught
# exception; otherwise prints the output and sets failed=1.
failed=0
expect() {
  name="$1"; expected="$2"; pattern="$3"
  problem=""
  if [ "$status" -eq 124 ]; then
    problem="timeout after $time_limit s (a hang?)"
  elif [ "$status" -ne "$expected" ]; then
    problem="exit status $status, expected $expected"
  elif ! printf '%s' "$output" | grep -Eq -- "$pattern"; then
    problem="no message matching <$pattern>"
  elif printf '%s' "$output" |
      grep -Eq "Stacktrace|received signal|Segmentation|Aborted"; then
    problem="a backtrace or crash report"
  elif printf '%s' "$output" | grep -q "exception is currently uncaught"; then
    problem="deal.II's TimerOutput paragraph about an uncaught exception"
  fi
  if [ -n "$problem" ]; then
    echo "FAIL: $name on $ranks rank(s): $problem"
    printf '%s\n' "$output" | tail -40
    failed=1
  else
    echo "OK: $name on $ranks rank(s): exit status $status, message <$pattern>"
  fi
}
