#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each one.
#   scripts/fuzz.sh [SECONDS] [TARGET...]        run each target for SECONDS (default 20)
#   scripts/fuzz.sh --runs N [TARGET...]         run each target for N executions
# TARGET is a name such as val_program (default: every tests/fuzz/fuzz_*.cpp). The build goes to
# $ARMMIMIC_FUZZ_BUILD_DIR (default build-fuzz). Each run starts from the seed corpus in
# tests/fuzz/corpus/<name>/ (never written to); new inputs go to <build>/fuzz/corpus/<name>/.
# On a crash or a broken property the input is kept as <build>/fuzz/crashes/<name>-crash-...,
# the other targets still run, and the script exits 1.
set -euo pipefail
cd "$(dirname "$0")/.."

limit=(-max_total_time=20)
if [[ "${1:-}" == "--runs" ]]; then
  [[ "${2:-}" =~ ^[0-9]+$ ]] || { echo "fuzz.sh: --runs needs a number of executions" >&2; exit 2; }
  limit=(-runs="$2")
  shift 2
elif [[ "${1:-}" =~ ^[0-9]+$ ]]; then
  limit=(-max_total_time="$1")
  shift
elif [[ "${1:-}" == -* ]]; then
  echo "fuzz.sh: unknown option $1 (usage: scripts/fuzz.sh [SECONDS | --runs N] [TARGET...])" >&2
  exit 2
fi

targets=("$@")
if ((${#targets[@]} == 0)); then
  for src in tests/fuzz/fuzz_*.cpp; do
    n="$(basename "$src" .cpp)"
    targets+=("${n#fuzz_}")
  done
fi
for t in "${targets[@]}"; do
  if [[ ! -f "tests/fuzz/fuzz_$t.cpp" ]]; then
    echo "fuzz.sh: no target '$t' (tests/fuzz/fuzz_$t.cpp does not exist)" >&2
    exit 2
  fi
done

BUILD_DIR="${ARMMIMIC_FUZZ_BUILD_DIR:-build-fuzz}"
if ! command -v clang++ >/dev/null; then
  echo "fuzz.sh: clang++ not found (scripts/deps.sh --with-extras installs clang)" >&2
  exit 1
fi
if [[ ! -f "$BUILD_DIR/build.ninja" ]]; then
  CC=clang CXX=clang++ cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DARMMIMIC_BUILD_FUZZ=ON -DARMMIMIC_BUILD_GUI=OFF -DARMMIMIC_BUILD_TESTS=OFF \
    -DARMMIMIC_BUILD_BENCH=OFF >/dev/null
fi
ninja -C "$BUILD_DIR" -j "${ARMMIMIC_JOBS:-$(nproc)}" "${targets[@]/#/fuzz_}" >&2

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
failed=()
mkdir -p "$BUILD_DIR/fuzz/crashes"
for t in "${targets[@]}"; do
  work="$BUILD_DIR/fuzz/corpus/$t"
  log="$BUILD_DIR/fuzz/$t.log"
  mkdir -p "$work"
  start=$(date +%s)
  rc=0
  "$BUILD_DIR/fuzz/fuzz_$t" "${limit[@]}" -max_len=4096 -timeout=10 -print_final_stats=1 \
    -artifact_prefix="$BUILD_DIR/fuzz/crashes/$t-" "$work" "tests/fuzz/corpus/$t" \
    >"$log" 2>&1 || rc=$?
  secs=$(($(date +%s) - start))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if ((rc == 0)); then
    echo "fuzz_$t: ok, ${runs:-?} executions in ${secs} s"
  else
    failed+=("$t")
    echo "fuzz_$t: FAILED (exit $rc) after ${secs} s; log $log" >&2
    grep -E "^(==[0-9]+==ERROR|SUMMARY|artifact_prefix|Test unit written)|runtime error" "$log" \
      | head -8 >&2 || true
  fi
done
if ((${#failed[@]} > 0)); then
  echo "fuzz.sh: failed: ${failed[*]} (inputs kept in $BUILD_DIR/fuzz/crashes/)" >&2
  exit 1
fi
