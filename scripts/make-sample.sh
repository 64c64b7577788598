#!/bin/sh
# Regenerates the bundled sample scene in data/sample/ (see data/README.md).
# Usage: scripts/make-sample.sh [path/to/armmimic-cli]
# Default CLI: build/bin/armmimic-cli relative to the repository root.
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
cli=${1:-"$root/build/bin/armmimic-cli"}
if [ ! -x "$cli" ]; then
  echo "make-sample.sh: $cli is not an executable armmimic-cli (build it, or pass its path)" >&2
  exit 2
fi

out="$root/data/sample"
# 45 empty-background frames, 60 standstill frames, 150 frames of mixed arm motion (thesis
# protocol), 320x240 MJPG with moderate sensor noise and a fixed seed.
"$cli" synth arm "$out" --seed 2026 --size 320x240 --fps 30 \
  --background-frames 45 --standstill-frames 60 --frames 150 \
  --noise 3 --codec MJPG --motion mixed --side right

total=$(du -sk "$out" | cut -f1)
echo "make-sample.sh: data/sample is ${total} KiB"
if [ "$total" -ge 5000 ]; then
  echo "make-sample.sh: data/sample is too large (${total} KiB, keep it under 5 MB)" >&2
  exit 1
fi
