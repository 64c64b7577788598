#!/usr/bin/env bash
# Behaviour check for restructuring: analyses a fixed set of generated scenes with every engine
# and calibration mode, and compares the angle files with those of another build.
#   scripts/behaviour.sh run CLI OUT_DIR [SCENES]   writes OUT_DIR/<case>.tsv (scenes made in
#                                                   SCENES, default OUT_DIR/scenes, if missing)
#   scripts/behaviour.sh compare OLD_DIR NEW_DIR
#   scripts/behaviour.sh check OLD_CLI NEW_CLI [WORK_DIR]   both of the above
# compare exits 1 unless every angle file is byte-identical, apart from the header keys listed
# in IGNORED_KEYS (keys removed on purpose; their removal is what the comparison forgives) and
# the source path, which names the folder the run was made in.
# The pose cases (pose engine, lk --auto-calibrate) run only when the pose model is in
# .cache/armmimic (scripts/deps.sh --with-model).
set -euo pipefail
cd "$(dirname "$0")/.."

# Header keys that a restructuring removed on purpose, with the reason in the commit that
# added them here. Everything else in the header and every row must stay the same.
IGNORED_KEYS=(
  bgsub.background_frames bgsub.compensate_drift bgsub.color_difference bgsub.reject_shadow
  bgsub.reject_head bgsub.near_shoulder bgsub.two_line_split bgsub.extent_yaw
  bgsub.bend_hysteresis bgsub.shoulder_from_arm_length bgsub.rest_pose bgsub.upper_from_person
)

usage() {
  sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

# The joints of frame F from a truth file: "--shoulder X,Y --elbow X,Y --wrist X,Y".
joints_at() {
  awk -F'\t' -v f="$2" '$1 == f { printf "--shoulder %d,%d --elbow %d,%d --wrist %d,%d",
    $7 + 0.5, $8 + 0.5, $9 + 0.5, $10 + 0.5, $11 + 0.5, $12 + 0.5 }' "$1"
}

run() {
  local cli="$1" out="$2" s="${3:-$2/scenes}"
  [[ -x "$cli" ]] || { echo "behaviour: $cli: not an executable" >&2; exit 2; }
  mkdir -p "$out" "$s"
  out="$(cd "$out" && pwd)"
  s="$(cd "$s" && pwd)"
  # Scenes: made once per folder, with whichever CLI runs first (the generator is not under test).
  [[ -f "$s/a7/scene.avi" ]] || "$cli" -q synth arm "$s/a7" --seed 7 --frames 150
  [[ -f "$s/a8/scene.avi" ]] || "$cli" -q synth arm "$s/a8" --seed 8 --frames 150 --motion bend --side left --shadow
  [[ -f "$s/r1/scene.avi" ]] || "$cli" -q synth arm "$s/r1" --random --seed 1001
  [[ -f "$s/r2/scene.avi" ]] || "$cli" -q synth arm "$s/r2" --random --seed 1002
  [[ -d "$s/m1" ]] || "$cli" -q synth marker "$s/m1" --seed 3
  local have_model=0
  [[ -f .cache/armmimic/movenet-lightning.bin ]] && have_model=1
  # Named for both programs: a copied one (the baseline) does not look in the source tree.
  if ((have_model)); then export ARMMIMIC_MODEL_DIR="$PWD/.cache/armmimic"; fi
  local a
  for a in a7 a8 r1 r2; do
    local d="$s/$a" bg=(--background-frames 45 --start 45 --arm-length "$s/$a/armlength.png")
    local start=105
    "$cli" -q analyze "$d/scene.avi" -o "$out/$a.bgsub.tsv" --engine bgsub "${bg[@]}"
    "$cli" -q analyze "$d/scene.avi" -o "$out/$a.bgsub-thesis.tsv" --engine bgsub --thesis "${bg[@]}"
    "$cli" -q analyze "$d/scene.avi" -o "$out/$a.lk.tsv" --engine lk --background-frames 45 --start 45
    "$cli" -q analyze "$d/scene.avi" -o "$out/$a.lk-thesis.tsv" --engine lk --thesis \
      --background-frames 45 --start 45
    # shellcheck disable=SC2046
    "$cli" -q analyze "$d/scene.avi" -o "$out/$a.lk-joints.tsv" --engine lk --start "$start" \
      $(joints_at "$d/truth.tsv" "$start")
    if ((have_model)); then
      "$cli" -q analyze "$d/scene.avi" -o "$out/$a.pose.tsv" --engine pose --start 45 || true
      "$cli" -q analyze "$d/scene.avi" -o "$out/$a.lk-auto.tsv" --engine lk --auto-calibrate \
        --start "$start" || true
    fi
  done
  local m="$s/m1"
  "$cli" -q analyze "$m"/views -o "$out/m1.marker.tsv" --engine marker --reference "$m/reference.png"
  "$cli" -q analyze "$m"/views -o "$out/m1.marker-thesis.tsv" --engine marker --thesis \
    --reference "$m/reference.png"
  echo "behaviour: $(ls "$out"/*.tsv | wc -l) angle files in $out"
}

# An angle file without the forgiven header keys and the source path.
normalised() {
  local keys="source" k
  for k in "${IGNORED_KEYS[@]}"; do keys+="|$k"; done
  sed -E "/^#/s/ (${keys//./\\.})=[^ ]*//g" "$1"
}

compare() {
  local old="$1" new="$2" bad=0 n=0 f
  for f in "$old"/*.tsv; do
    local name
    name="$(basename "$f")"
    n=$((n + 1))
    if [[ ! -f "$new/$name" ]]; then
      echo "behaviour: $name: missing in $new"
      bad=$((bad + 1))
    elif ! cmp -s <(normalised "$f") <(normalised "$new/$name"); then
      echo "behaviour: $name: differs"
      diff <(normalised "$f") <(normalised "$new/$name") | head -6
      bad=$((bad + 1))
    fi
  done
  ((n > 0)) || { echo "behaviour: no angle files in $old" >&2; exit 2; }
  if ((bad)); then
    echo "behaviour: $bad of $n angle files differ"
    return 1
  fi
  echo "behaviour: all $n angle files identical"
}

case "${1:-}" in
  run) (($# == 3 || $# == 4)) || usage; run "$2" "$3" "${4:-$3/scenes}" ;;
  compare) (($# == 3)) || usage; compare "$2" "$3" ;;
  check)
    (($# >= 3)) || usage
    work="${4:-$(mktemp -d "${TMPDIR:-/tmp}/armmimic-behaviour-XXXXXX")}"
    run "$2" "$work/old" "$work/scenes"
    run "$3" "$work/new" "$work/scenes"
    compare "$work/old" "$work/new"
    ;;
  *) usage ;;
esac
