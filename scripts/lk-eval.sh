#!/usr/bin/env bash
# Accuracy of the LK engine through MJPG files, the way an operator runs it: renders a set of
# arm scenes (seeds, motions, sides, shadow, drift, noise, contrast, codec), analyses each with
# `armmimic-cli analyze --engine lk` twice (background + standstill, and from the given
# shoulder), scores the angle files against the truth and prints per-scene and mean errors.
#   scripts/lk-eval.sh [BUILD_DIR] [WORK_DIR]   (defaults: build, a new temporary folder)
# Scenes already in WORK_DIR are reused. Extra analyze flags can be passed in LK_EVAL_FLAGS.
# LK_EVAL_SET=heldout scores 28 other scenes instead (other seeds, sizes, frame rates, codecs,
# the yaw motion), kept apart from the ones the engine was tuned on.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
CLI="$BUILD_DIR/bin/armmimic-cli"
[[ -x "$CLI" ]] || { echo "lk-eval: $CLI not found; build first (scripts/build.sh $BUILD_DIR)" >&2; exit 2; }
WORK="${2:-$(mktemp -d /tmp/armmimic-lk-eval-XXXXXX)}"
mkdir -p "$WORK"
read -r -a EXTRA <<<"${LK_EVAL_FLAGS:-}"

# name: synth arm options
TUNING=(
  "m3:--seed 3"
  "m4:--seed 4"
  "m5:--seed 5 --side left"
  "m6:--seed 6 --shadow --head-motion"
  "b7:--seed 7 --motion bend"
  "b8:--seed 8 --motion bend --side left --drift 0.2"
  "s9:--seed 9 --motion swing"
  "m10:--seed 10 --frames 300"
  "c11:--seed 11 --contrast 0.5"
  "x12:--seed 12 --codec XVID"
  "h21:--seed 21 --frames 200"
  "h22:--seed 22 --frames 200 --side left --shadow"
  "h23:--seed 23 --motion bend --head-motion"
  "h24:--seed 24 --frames 200 --noise 6"
  "h25:--seed 25 --frames 200 --contrast 0.7 --drift 0.15"
  "h26:--seed 26 --motion swing --side left"
)
HELDOUT=(
  "b401:--seed 401 --contrast 0"
  "b402:--seed 402 --motion yaw"
  "b403:--seed 403 --size 160x120"
  "b404:--seed 404 --size 800x600"
  "b405:--seed 405 --fps 15"
  "b406:--seed 406 --frames 1500"
  "b407:--seed 407 --noise 10"
  "b408:--seed 408 --codec H264"
  "b409:--seed 409 --contrast 0.3 --side left"
  "b410:--seed 410 --motion bend --shadow --drift 0.3"
  "b411:--seed 411 --head-motion --frames 400"
  "b412:--seed 412 --contrast 2"
  "b413:--seed 413 --motion swing --size 640x480 --noise 6"
  "b414:--seed 414 --frames 100"
  "b415:--seed 415 --standstill-frames 30 --background-frames 20"
  "b416:--seed 416 --quality 30"
  "y501:--seed 501 --motion yaw"
  "y502:--seed 502 --motion yaw --side left"
  "y503:--seed 503 --motion yaw"
  "y504:--seed 504 --motion yaw --frames 300 --size 640x480"
  "c601:--seed 601"
  "c602:--seed 602 --side left --motion bend"
  "c603:--seed 603 --motion yaw --shadow"
  "c604:--seed 604 --motion swing --head-motion --noise 5"
  "c605:--seed 605 --frames 400 --drift 0.1"
  "c606:--seed 606 --size 640x480 --motion bend --side left"
  "c607:--seed 607 --contrast 0.5 --motion swing"
  "c608:--seed 608 --codec XVID --side left"
)
if [[ "${LK_EVAL_SET:-tuning}" == "heldout" ]]; then SCENES=("${HELDOUT[@]}"); else SCENES=("${TUNING[@]}"); fi

# Prints "coverage upper_mae fore_mae overall_mae" for an angle file.
score() {
  "$CLI" score "$1" "$2" | awk '
    /^  coverage:/ { cov = $2 }
    /^direction error/ { d = 1; next }
    d && $1 == "upper" { u = $4 }
    d && $1 == "fore" { f = $4 }
    d && $1 == "overall:" { o = $3; d = 0 }
    END { printf "%s %s %s %s", cov, u, f, o }'
}

printf '%-5s %-50s | %-30s | %-30s\n' scene options "background: cov upper fore all" \
  "given shoulder: cov upper fore all"
sum_bg=(0 0 0) sum_sh=(0 0 0) n=0
for entry in "${SCENES[@]}"; do
  name="${entry%%:*}"
  read -r -a opts <<<"${entry#*:}"
  dir="$WORK/$name"
  [[ -f "$dir/truth.tsv" ]] || "$CLI" -q synth arm "$dir" --frames 150 "${opts[@]}"
  # The recording protocol from the truth's meta line; the shoulder from its last standstill row.
  k=$(grep -o 'background_frames=[0-9]*' "$dir/truth.tsv" | cut -d= -f2)
  m=$(grep -o 'standstill_frames=[0-9]*' "$dir/truth.tsv" | cut -d= -f2)
  last=$((k + m - 1))
  shoulder=$(awk -F'\t' -v f="$last" '!/^#/ && $1 == f { printf "%.0f,%.0f", $7, $8 }' \
    "$dir/truth.tsv")
  "$CLI" -q analyze "$dir/scene.avi" -o "$dir/bg.tsv" --engine lk --background-frames "$k" \
    --start "$k" --standstill-frames "$m" "${EXTRA[@]}"
  "$CLI" -q analyze "$dir/scene.avi" -o "$dir/sh.tsv" --engine lk --shoulder "$shoulder" \
    --start "$last" "${EXTRA[@]}"
  read -r c1 u1 f1 o1 <<<"$(score "$dir/truth.tsv" "$dir/bg.tsv")"
  read -r c2 u2 f2 o2 <<<"$(score "$dir/truth.tsv" "$dir/sh.tsv")"
  printf '%-5s %-50s | %-7s %5s %5s %5s       | %-7s %5s %5s %5s\n' "$name" "${entry#*:}" \
    "$c1" "$u1" "$f1" "$o1" "$c2" "$u2" "$f2" "$o2"
  sum_bg=($(echo "${sum_bg[0]} + $u1; ${sum_bg[1]} + $f1; ${sum_bg[2]} + $o1" | bc))
  sum_sh=($(echo "${sum_sh[0]} + $u2; ${sum_sh[1]} + $f2; ${sum_sh[2]} + $o2" | bc))
  n=$((n + 1))
done
mean() { echo "scale=2; $1 / $n" | bc; }
printf '%-56s | %-7s %5s %5s %5s       | %-7s %5s %5s %5s\n' "mean of $n scenes (MAE, degrees)" \
  "" "$(mean "${sum_bg[0]}")" "$(mean "${sum_bg[1]}")" "$(mean "${sum_bg[2]}")" \
  "" "$(mean "${sum_sh[0]}")" "$(mean "${sum_sh[1]}")" "$(mean "${sum_sh[2]}")"
echo "scenes and angle files: $WORK"
