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
# -O2 as in the release build, so the optimiser meets the same code; -g1 (line tables only) is
# all a sanitizer report needs for file:line, and it halves the debug info that the build writes
# and that the leak check's symbolizer reads at the end of every test process.
# Each GoogleTest suite runs as one ctest test (ARMMIMIC_TEST_PER_SUITE): a sanitized process
# is slow to start and to leave (the leak check), and paying that once per suite instead of once
# per test cut the suite's time by about a quarter (460 s to 331 s on 2 cores). A finding still
# names its test: the output ctest shows on failure holds gtest's [ RUN ] line before it. The
# timeout is per suite.
scripts/build.sh "$BUILD_DIR" -DARMMIMIC_SANITIZE=ON -DARMMIMIC_BUILD_BENCH=OFF \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" -DARMMIMIC_TEST_PER_SUITE=ON "$@" >&2
scripts/run-ctest.sh "$BUILD_DIR" --output-on-failure -j "${ARMMIMIC_TEST_JOBS:-$(nproc)}" \
  --timeout "${ARMMIMIC_TEST_TIMEOUT:-1500}"
