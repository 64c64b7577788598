#!/usr/bin/env bash
# Builds armmimic and runs the whole test suite through ctest; a test that did not run (one that
# reported itself skipped) fails the run.
#   scripts/test.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
# The pose engine's tests need its model (registered only when it is there at configure time).
scripts/deps.sh --with-model
scripts/build.sh "$@" >&2
scripts/run-ctest.sh "$BUILD_DIR" --output-on-failure -j "${ARMMIMIC_TEST_JOBS:-$(nproc)}"
