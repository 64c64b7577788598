#!/usr/bin/env bash
# Live mimicking end to end, timed (docs/live.md): renders an arm scene of SECONDS of motion at
# 320x240 and 640x480, and streams each, paced at its frame rate, with
#   armmimic-cli mimic scene.avi --realtime --engine lk --shoulder/--elbow/--wrist (clicked)
# to the built-in emulator twice: at the pseudo-terminal's speed, and answering like a VAL
# terminal on a 9600-baud RS-232 line (puma-sim --line-baud 9600). Motions take their real time.
# Prints each run's latency summary (frame-to-command median and p95, commands per second,
# moves acknowledged of sent); the per-frame logs stay in WORK_DIR.
#   scripts/live-latency.sh [BUILD_DIR] [WORK_DIR] [SECONDS]   (defaults: build, a temp dir, 60)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
CLI="$BUILD_DIR/bin/armmimic-cli"
[[ -x "$CLI" ]] || { echo "live-latency: $CLI not found; build first" >&2; exit 2; }
WORK="${2:-$(mktemp -d /tmp/armmimic-live-XXXXXX)}"
SECONDS_OF_MOTION="${3:-60}"
mkdir -p "$WORK"
BG=10
STILL=20
FRAMES=$((SECONDS_OF_MOTION * 30))

# The truth's shoulder, elbow and wrist in frame $2 of truth file $1, rounded: "X,Y X,Y X,Y".
clicks() {
  awk -F'\t' -v f="$2" '$1 == f {
    printf "%d,%d %d,%d %d,%d\n", $7 + 0.5, $8 + 0.5, $9 + 0.5, $10 + 0.5, $11 + 0.5, $12 + 0.5
  }' "$1"
}

for size in 320x240 640x480; do
  scene="$WORK/scene-$size"
  if [[ ! -f "$scene/truth.tsv" ]]; then
    "$CLI" -q synth arm "$scene" --seed 31 --size "$size" --frames "$FRAMES" \
      --background-frames "$BG" --standstill-frames "$STILL" --motion mixed
  fi
  read -r shoulder elbow wrist < <(clicks "$scene/truth.tsv" $((BG + STILL)))
  for line in pty 9600; do
    run="$WORK/$size-$line"
    sim_args=(--link "$run.puma" --log "$run.moves")
    [[ $line == 9600 ]] && sim_args+=(--line-baud 9600)
    "$CLI" -q puma-sim "${sim_args[@]}" > "$run.sim" &
    sim=$!
    for _ in $(seq 50); do [[ -e "$run.puma" ]] && break; sleep 0.1; done
    echo "== $size, controller: emulator ($([[ $line == pty ]] && echo 'pseudo-terminal speed' ||
      echo 'VAL terminal at 9600 baud'))"
    "$CLI" --no-progress -q mimic "$scene/scene.avi" --realtime --engine lk --start $((BG + STILL)) \
      --shoulder "$shoulder" --elbow "$elbow" --wrist "$wrist" --port "$run.puma" \
      -o "$run.tsv" || echo "live-latency: mimic exited $?" >&2
    kill -INT "$sim" 2>/dev/null || true
    wait "$sim" 2>/dev/null || true
    echo "   moves the emulator ran: $(wc -l < "$run.moves")"
  done
done
echo "logs: $WORK"
