#!/usr/bin/env bash
# Scores the pose engine, both arms: median, p90 and >30 degree share of the direction errors
# over ok rows, coverage (ok segments / segments) and the confidently-wrong rate (ok with error
# > 15 degrees).
#   scripts/pose-eval.sh [BUILD_DIR] [REAL_DIR]   (defaults: build, ../shared/real)
# The real clip against its reference keypoints (the pose engine, then LK with
# --auto-calibrate). Needs the model (scripts/deps.sh --with-model) and the clip.
#   POSE_EVAL_SET=synth scripts/pose-eval.sh [BUILD_DIR]
# Generated scenes against their truth instead: twelve scenes from the tuning seeds 1000-1011
# (motions, sides, head motion, shadow, drift, contrast, 640x480), the person's moving arm.
# POSE_EVAL_FLAGS holds extra analyze flags for the pose runs ("--param pose.flip=true").
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
REAL="${2:-../shared/real}"
CLI="$BUILD_DIR/bin/armmimic-cli"
read -r -a EXTRA <<<"${POSE_EVAL_FLAGS:-}"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# errors ANGLES.tsv REFERENCE UPPER_COL FORE_COL -> "ok ERR" per segment, "lost" per lost one,
# for the frames the reference has directions for.
errors() {
  awk -F'\t' -v cu="$3" -v cf="$4" '
    function wrap(a) { while (a > 180) a -= 360; while (a <= -180) a += 360; return a < 0 ? -a : a }
    FNR == NR { if ($1 ~ /^[0-9]+$/ && $cu != "nan") { ru[$1] = $cu; rf[$1] = $cf } next }
    /^#/ || $1 == "frame" { next }
    !($1 in ru) { next }
    $3 == "ok" { print "ok", wrap($4 - ru[$1]); print "ok", wrap($5 - rf[$1]); next }
    { print "lost"; print "lost" }' "$2" "$1"
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

[[ -x "$CLI" ]] || { echo "pose-eval: $CLI not found; build first" >&2; exit 1; }

if [[ "${POSE_EVAL_SET:-real}" == synth ]]; then
  SCENES=(
    "--seed 1000" "--seed 1001 --side left" "--seed 1002 --motion yaw"
    "--seed 1003 --motion bend --side left" "--seed 1004 --motion swing"
    "--seed 1005 --head-motion" "--seed 1006 --side left --contrast 0.3"
    "--seed 1007 --motion yaw --side left" "--seed 1008 --motion bend --shadow"
    "--seed 1009 --size 640x480" "--seed 1010 --side left --head-motion --drift 0.3"
    "--seed 1011 --motion swing --side left"
  )
  for i in "${!SCENES[@]}"; do
    read -r -a opts <<<"${SCENES[$i]}"
    dir="$OUT/scene$i"
    "$CLI" -q synth arm "$dir" "${opts[@]}" --background-frames 3 --standstill-frames 10 \
      --frames 120
    side=left  # the scene's moving arm on the image's right is the person's left
    [[ " ${SCENES[$i]} " == *" --side left "* ]] && side=right
    "$CLI" -q analyze "$dir/scene.avi" -o "$dir/pose.tsv" --engine pose --side "$side" \
      "${EXTRA[@]}"
    errors "$dir/pose.tsv" "$dir/truth.tsv" 3 4 > "$dir/pose.err"
    summary "synth ${SCENES[$i]}" < "$dir/pose.err"
  done
  cat "$OUT"/scene*/pose.err | summary "pose, all scenes"
  exit 0
fi

CLIP="$REAL/pose_squats.mp4"
REF="$REAL/pose_squats.keypoints.tsv"
for f in "$CLIP" "$REF"; do
  [[ -e "$f" ]] || { echo "pose-eval: $f not found" >&2; exit 1; }
done
cols() { [[ "$1" == left ]] && echo "14 15" || echo "16 17"; }
for side in left right; do
  "$CLI" -q analyze "$CLIP" -o "$OUT/pose_$side.tsv" --engine pose --side "$side" "${EXTRA[@]}"
  # shellcheck disable=SC2046
  errors "$OUT/pose_$side.tsv" "$REF" $(cols "$side") > "$OUT/pose_$side.err"
  summary "pose --side $side" < "$OUT/pose_$side.err"
done
cat "$OUT"/pose_*.err | summary "pose, both arms"
for side in left right; do
  if "$CLI" -q analyze "$CLIP" -o "$OUT/lk_$side.tsv" --engine lk --auto-calibrate \
      --side "$side" 2> "$OUT/lk_$side.log"; then
    # shellcheck disable=SC2046
    errors "$OUT/lk_$side.tsv" "$REF" $(cols "$side") > "$OUT/lk_$side.err"
    summary "lk --auto-calibrate --side $side" < "$OUT/lk_$side.err"
  else
    echo "lk --auto-calibrate --side $side: $(cat "$OUT/lk_$side.log")"
  fi
done
cat "$OUT"/lk_*.err 2>/dev/null | summary "lk --auto-calibrate, both"
