#!/usr/bin/env bash
# The standstill self-calibration against the truth (docs/accuracy.md, "Calibrating from the
# standstill"): for every scene folder of a protocol-eval work folder (scene.avi, truth.tsv,
# background.png, armlength.png), runs `armmimic-cli analyze --engine lk` with the thesis
# protocol and no clicks, reads the joints it prints (`estimated: lk: calibrated ...`) and
# measures them against the truth's joints in the last standstill frame, the frame the
# calibration places them in. Prints one row per scene, then per generator and tier the
# calibrated share and the median and largest error of each joint.
#
#   scripts/calibration-eval.sh [--build DIR] WORK_DIR...
#
# Columns: shoulder, elbow and wrist distance from the truth (px); wrist_len, the estimated
# shoulder-to-wrist length over the truth's (the wrist is placed at an anthropometric share of
# the reach, so this says how far the figure's hand differs from that share); reach_len, the
# measured shoulder-to-fingertip reach over the truth's shoulder-to-wrist length. A refused
# calibration prints its reason. The scenes are only read: nothing is written to them.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=build
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
WORKS=()
while (($# > 0)); do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "calibration-eval.sh: unknown flag $1 (see --help)" >&2; exit 2 ;;
    *) WORKS+=("$1"); shift ;;
  esac
done
((${#WORKS[@]} > 0)) || { usage >&2; exit 2; }
CLI="$BUILD/bin/armmimic-cli"
[[ -x "$CLI" ]] || { echo "calibration-eval.sh: $CLI not found: build first (scripts/build.sh)" >&2; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# The value of KEY in TRUTH's header line (as protocol-eval.sh reads it).
meta() { sed -n '2p' "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }

rows="$TMP/rows.tsv"
printf 'scene\tgenerator\ttier\tshoulder\telbow\twrist\twrist_len\treach_len\tnote\n' >"$rows"
for work in "${WORKS[@]}"; do
  [[ -d "$work" ]] || { echo "calibration-eval.sh: $work: no such folder" >&2; exit 2; }
  for dir in "$work"/*/; do
    dir=${dir%/}
    truth="$dir/truth.tsv"
    [[ -f "$truth" && -f "$dir/scene.avi" && -f "$dir/background.png" && -f "$dir/armlength.png" ]] || continue
    k=$(meta "$truth" background_frames)
    m=$(meta "$truth" standstill_frames)
    generator=$(meta "$truth" generator)
    [[ -n "$generator" ]] || generator=random
    tier=$(meta "$truth" tier)
    log="$TMP/log"
    "$CLI" analyze "$dir/scene.avi" -o "$TMP/angles.tsv" --engine lk \
      --background "$dir/background.png" --arm-length "$dir/armlength.png" \
      --start "$k" --standstill-frames "$m" >"$log" 2>&1 || true
    awk -F'\t' -v f=$((k + m - 1)) -v scene="$(basename "$dir")" -v g="$generator" -v t="$tier" \
      -v est="$(grep -m1 'estimated: lk:' "$log" || true)" '
      function d(ax, ay, bx, by) { return sqrt((ax - bx) ^ 2 + (ay - by) ^ 2) }
      $1 == f {
        if (match(est, /shoulder [0-9.]+,[0-9.]+, elbow [0-9.]+,[0-9.]+, wrist [0-9.]+,[0-9.]+/)) {
          s = substr(est, RSTART, RLENGTH); gsub(/[a-z,]+/, " ", s); split(s, j, " ")
          r = est; sub(/.*reach /, "", r); sub(/ px.*/, "", r)
          tl = d($7, $8, $11, $12)
          printf "%s\t%s\t%s\t%.1f\t%.1f\t%.1f\t%.2f\t%.2f\tcalibrated\n", scene, g, t,
            d(j[1], j[2], $7, $8), d(j[3], j[4], $9, $10), d(j[5], j[6], $11, $12),
            d(j[1], j[2], j[5], j[6]) / tl, r / tl
        } else {
          why = est; sub(/.*estimated: lk: /, "", why)
          if (why == "") why = "no estimate printed"
          printf "%s\t%s\t%s\tnan\tnan\tnan\tnan\tnan\t%s\n", scene, g, t, why
        }
      }' "$truth" >>"$rows"
  done
done
column -t -s $'\t' "$rows"
echo
awk -F'\t' '
  function q(list, p,   a, n) { n = split(list, a, " "); asort(a); return n ? a[int(p * (n - 1) + 0.5) + 1] : "nan" }
  NR > 1 {
    key = $2 " " $3; n[key]++
    if ($9 == "calibrated") { c[key]++; sh[key] = sh[key] " " $4; el[key] = el[key] " " $5; wr[key] = wr[key] " " $6; wl[key] = wl[key] " " $7 }
  }
  END {
    for (key in n) printf "%-16s %2d of %-4d %8s / %-11s %8s / %-11s %8s / %-11s %s\n", key, c[key], n[key], q(sh[key], 0.5), q(sh[key], 1), q(el[key], 0.5), q(el[key], 1), q(wr[key], 0.5), q(wr[key], 1), q(wl[key], 0.5)
  }' "$rows" | sort | { printf "%-16s %-10s %-22s %-22s %-22s %s\n" "generator tier" "calibrated" \
  "shoulder px (med/max)" "elbow px (med/max)" "wrist px (med/max)" "wrist_len (med)"; cat; }
