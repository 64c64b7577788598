#!/usr/bin/env bash
# Scores the pose engine (and LK with --auto-calibrate) on the real clip with reference
# keypoints, both arms: median, p90 and >30 degree share of the direction errors over ok rows,
# coverage (ok rows / rows) and the confidently-wrong rate (ok with error > 15 degrees).
#   scripts/pose-eval.sh [BUILD_DIR] [REAL_DIR]   (defaults: build, ../shared/real)
# Needs the model (scripts/deps.sh --with-model) and the clip; prints one line per run and both
# arms together.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
REAL="${2:-../shared/real}"
CLI="$BUILD_DIR/bin/armmimic-cli"
CLIP="$REAL/pose_squats.mp4"
REF="$REAL/pose_squats.keypoints.tsv"
for f in "$CLI" "$CLIP" "$REF"; do
  [[ -e "$f" ]] || { echo "pose-eval: $f not found" >&2; exit 1; }
done
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# score ANGLES.tsv SIDE -> "errors" lines on stdout ("ok ERR" per segment, "lost" per lost row)
errors() {
  awk -F'\t' -v side="$2" '
    function wrap(a) { while (a > 180) a -= 360; while (a <= -180) a += 360; return a < 0 ? -a : a }
    FNR == NR { if ($1 ~ /^[0-9]+$/) { ru[$1] = (side == "left") ? $14 : $16;
                                       rf[$1] = (side == "left") ? $15 : $17 } next }
    /^#/ || $1 == "frame" { next }
    !($1 in ru) { next }
    $3 == "ok" { print "ok", wrap($4 - ru[$1]); print "ok", wrap($5 - rf[$1]); next }
    { print "lost"; print "lost" }' "$REF" "$1"
}

summary() {  # NAME, then error lines on stdin
  sort -k2,2g | awk -v name="$1" '
    $1 == "ok" { e[n++] = $2; if ($2 > 30) big++; if ($2 > 15) wrong++; next }
    { lost++ }
    END {
      if (n == 0) { printf "%-28s no ok rows (%d segments lost)\n", name, lost; exit }
      printf "%-28s median %5.1f  p90 %5.1f  coverage %5.1f %%  >15: %4.1f %%  >30: %4.1f %% of ok (%d segments)\n",
        name, e[int((n - 1) / 2)], e[int((n - 1) * 0.9)], 100 * n / (n + lost), 100 * wrong / n,
        100 * big / n, n + lost }'
}

all=()
for side in left right; do
  "$CLI" -q analyze "$CLIP" -o "$OUT/pose_$side.tsv" --engine pose --side "$side"
  errors "$OUT/pose_$side.tsv" "$side" > "$OUT/pose_$side.err"
  summary "pose --side $side" < "$OUT/pose_$side.err"
done
cat "$OUT"/pose_*.err | summary "pose, both arms"
for side in left right; do
  if "$CLI" -q analyze "$CLIP" -o "$OUT/lk_$side.tsv" --engine lk --auto-calibrate \
      --side "$side" 2> "$OUT/lk_$side.log"; then
    errors "$OUT/lk_$side.tsv" "$side" > "$OUT/lk_$side.err"
    summary "lk --auto-calibrate --side $side" < "$OUT/lk_$side.err"
  else
    echo "lk --auto-calibrate --side $side: $(cat "$OUT/lk_$side.log")"
  fi
done
cat "$OUT"/lk_*.err 2>/dev/null | summary "lk --auto-calibrate, both"
