#!/usr/bin/env bash
# Runs one GoogleTest executable for ctest. A failure stays a failure; a run in which any test skipped itself
# (GTEST_SKIP) exits 77, which the test's SKIP_RETURN_CODE makes ctest show as skipped instead of passed.
set -uo pipefail
log=$(mktemp)
trap 'rm -f "$log"' EXIT
"$@" >"$log" 2>&1
rc=$?
cat "$log"
((rc != 0)) && exit "$rc"
if grep -q '^\[  SKIPPED \]' "$log"; then
  echo "run_gtest: $(grep -c '^\[  SKIPPED \] [A-Za-z]' "$log") test(s) skipped (listed above): ctest shows this executable as skipped"
  exit 77
fi
exit 0
