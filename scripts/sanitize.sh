#!/usr/bin/env bash
# Builds armmimic with AddressSanitizer + UndefinedBehaviorSanitizer in build-asan (or the given
# directory) and runs the whole test suite there. Any sanitizer report fails the test it hit.
#   scripts/sanitize.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build-asan}"
shift || true
# Leak checking stays on; a UBSan report aborts (the build uses -fno-sanitize-recover=undefined).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp:print_suppressions=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export QT_QPA_PLATFORM="${QT_QPA_PLATFORM:-offscreen}"
scripts/build.sh "$BUILD_DIR" -DARMMIMIC_SANITIZE=ON -DARMMIMIC_BUILD_BENCH=OFF "$@" >&2
scripts/run-ctest.sh "$BUILD_DIR" --output-on-failure -j "${ARMMIMIC_TEST_JOBS:-$(nproc)}" \
  --timeout "${ARMMIMIC_TEST_TIMEOUT:-300}"
