#!/usr/bin/env bash
# The main job on the bundled sample: build if needed, estimate the background, analyse the
# video with the background-subtraction engine, and print the score against the sample's truth.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh build >&2
CLI=build/bin/armmimic-cli
OUT="${ARMMIMIC_OUT:-out}"
mkdir -p "$OUT"
S=data/sample
set -x
"$CLI" background "$S/scene.avi" -o "$OUT/background.png" --frames 45
"$CLI" analyze "$S/scene.avi" -o "$OUT/angles.tsv" --engine bgsub \
  --background "$OUT/background.png" --arm-length "$S/armlength.png" --start 45
"$CLI" score "$S/truth.tsv" "$OUT/angles.tsv" --plot "$OUT/error.png"
