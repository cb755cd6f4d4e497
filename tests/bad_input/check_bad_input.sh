#!/bin/sh
# Usage: check_bad_input.sh <program> <prm file> <pattern>
# Passes if <program> exits with a non-zero status, prints an error message
# matching <pattern> (grep -E), and neither crashes nor hangs.
program="$1"; prm="$2"; pattern="$3"
output=$(timeout 60 "$program" "$prm" 2>&1)
status=$?
if [ $status -eq 0 ]; then
  echo "FAIL: exit status 0 for $prm"; exit 1
fi
if [ $status -ge 124 ]; then
  echo "FAIL: timeout or crash (status $status) for $prm"; echo "$output"; exit 1
fi
if ! printf '%s' "$output" | grep -Eq "$pattern"; then
  echo "FAIL: message does not match <$pattern>:"; echo "$output"; exit 1
fi
echo "OK: $prm exits with status $status and the expected message"
