#!/usr/bin/env bash
# Runs the suite in BUILD_DIR through ctest and fails when any test did not run, e.g. one that
# reported itself skipped: a skipped test proves nothing, so CI counts it as a failure.
#   scripts/run-ctest.sh BUILD_DIR [ctest args...]
set -euo pipefail
BUILD_DIR="$1"
shift
junit="$(cd "$BUILD_DIR" && pwd)/ctest-results.xml"
rm -f "$junit"
rc=0
ctest --test-dir "$BUILD_DIR" --output-junit "$junit" "$@" || rc=$?
if [[ ! -f "$junit" ]]; then
  echo "run-ctest: ctest wrote no results ($junit)" >&2
  exit $((rc == 0 ? 1 : rc))
fi
notrun=$(grep -c 'status="notrun"' "$junit" || true)
if ((notrun > 0)); then
  echo "run-ctest: $notrun test(s) did not run (skipped or disabled); every test must run:" >&2
  grep 'status="notrun"' "$junit" | sed -e 's/.*<testcase name="\([^"]*\)".*/  \1/' >&2
  exit 1
fi
exit "$rc"
