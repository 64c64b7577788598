#!/usr/bin/env bash
# Accuracy of the marker engine the way an operator runs it: renders marker-joint scenes in three
# tiers with `armmimic-cli synth marker`, analyses each with `armmimic-cli analyze --engine
# marker`, joins the angle files with the truth and prints, per tier, the yaw and bend errors,
# how many readable views were answered, how many unreadable views were (wrongly) answered,
# the worst error within 5 degrees of zero yaw and the confidently-wrong views (ok, error > 15).
#   scripts/marker-eval.sh [BUILD_DIR] [WORK_DIR]   (defaults: build, a new temporary folder)
# Tiers (docs/marker.md): easy = plain or gradient background, normal light; medium = any
# background and light; hard = medium with 8 dark marker-like blobs and noise 3.
# Each scene gives 24 views with yaw in [-135, 135] and 6 views with yaw in [-5, 5], bend in
# [-60, 60]. MARKER_EVAL_SET=tuning (default; seeds 1-10, 101-110, 201-210, or with
# MARKER_EVAL_SEEDS=N up to 99 the first N of each hundred: every seed below 1000 is for tuning)
# or heldout (seeds 1001-1010, 1101-1110, 1201-1210: never used for tuning). MARKER_EVAL_SYNTH
# adds synth flags
# (e.g. "--fov 45" to render with another lens than the engine assumes), MARKER_EVAL_FLAGS
# analyze flags (with --thesis, its unsigned yaw is scored against |yaw|). Scenes already in
# WORK_DIR are reused.
# Columns: readable = views with a lower marker facing the camera within 75 degrees; answered =
# their share read (ok); yaw_mae/max/bias = error of the signed yaw over those; near0_max = the
# largest yaw error within 5 degrees of zero / how many such views were read; bend_mae/max over
# the views read with a bend; bend_read = share of views whose upper marker faces the camera
# within 75 degrees that got a bend; wrong = views read with an error over 15 degrees.
#
# MARKER_EVAL_MODE=renderers compares both renderers instead (docs/marker.md, "Two renderers"):
# `synth marker` (--renderer scene) and the independent `synth marker --renderer rig`, three sets
# each (easy, medium, hard), 7 scenes of 4 views = 28 views per set, yaw in [-60, 60], bend in
# [-60, 60]. The rig's own lens (its truth.tsv's fov_deg) is given to analyze as --fov. Seeds:
# MARKER_EVAL_SET=heldout (default here) 5001-5007, 5101-5107, 5201-5207, never used to tune
# anything; tuning: 1-12, 101-112, 201-212 (MARKER_EVAL_SEEDS=N the first N of each hundred;
# MARKER_EVAL_FIRST=K starts each hundred at seed K instead of 1, e.g. 31 for the validation
# rigs 31-99, 131-199, 231-299). MARKER_EVAL_RENDERERS="rig" (or "scene") runs one renderer only.
# Columns: answered (ok rows of 28), readable (views with a lower marker facing the camera within
# 75 degrees), yaw_mae (yaw_deg against |yaw|, answered views), bend_mae (answered with a bend),
# signed_max (largest error of an answered signed yaw), signed_off5 (answered signed yaws more
# than 5 degrees off), signed_nan (answered rows whose sign was not told).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
CLI="$BUILD_DIR/bin/armmimic-cli"
[[ -x "$CLI" ]] || { echo "marker-eval: $CLI not found; build first (scripts/build.sh $BUILD_DIR)" >&2; exit 2; }
WORK="${2:-$(mktemp -d /tmp/armmimic-marker-eval-XXXXXX)}"
mkdir -p "$WORK"

if [[ "${MARKER_EVAL_MODE:-tiers}" == renderers ]]; then
  case "${MARKER_EVAL_SET:-heldout}" in
    heldout) FIRST=5001; SCENES=7 ;;
    tuning) FIRST="${MARKER_EVAL_FIRST:-1}"; SCENES="${MARKER_EVAL_SEEDS:-12}" ;;
    *) echo "marker-eval: MARKER_EVAL_SET must be tuning or heldout" >&2; exit 2 ;;
  esac
  declare -A SCENE_FLAGS=(
    [easy]="--background simple --lighting normal"
    [medium]="--background mixed --lighting mixed"
    [hard]="--background mixed --lighting mixed --clutter 8 --noise 3"
  )
  declare -A BASE=([easy]=0 [medium]=100 [hard]=200)
  ROWS="$WORK/renderer-rows.tsv"
  : >"$ROWS"
  if [[ "${MARKER_EVAL_SET:-heldout}" == tuning ]] && ((FIRST < 1 || FIRST + SCENES - 1 > 99)); then
    echo "marker-eval: tuning seeds must stay within 1..99 of each hundred" >&2
    exit 2
  fi
  for renderer in ${MARKER_EVAL_RENDERERS:-scene rig}; do
    case "$renderer" in scene | rig) ;; *)
      echo "marker-eval: MARKER_EVAL_RENDERERS lists scene and/or rig" >&2
      exit 2
      ;;
    esac
    for set in easy medium hard; do
      for ((k = 0; k < SCENES; k++)); do
        seed=$((FIRST + BASE[$set] + k))
        dir="$WORK/$renderer-$set-$seed"
        if [[ $renderer == rig ]]; then
          synth=(--renderer rig --set "$set")
        else
          read -r -a synth <<<"${SCENE_FLAGS[$set]}"
        fi
        if [[ ! -f "$dir/truth.tsv" ]]; then
          "$CLI" -q synth marker "$dir" --seed "$seed" --views 4 --max-yaw 60 --max-bend 60 "${synth[@]}"
        fi
        fov=$(sed -n 's/.* fov_deg=\([0-9.]*\).*/\1/p' "$dir/truth.tsv" | head -1)
        if ! "$CLI" -q analyze "$dir/views" -o "$dir/angles.tsv" --engine marker \
          --reference "$dir/reference.png" --fov "${fov:-60}" 2>"$dir/analyze.err"; then
          echo "marker-eval: $renderer $set seed $seed: $(tail -1 "$dir/analyze.err")" >&2
          awk -F'\t' -v r="$renderer" -v s="$set" '/^#/ { next }
            $1 == "frame" { for (i = 1; i <= NF; i++) t[$i] = i; next }
            { print r, s, $t["yaw_signed_deg"], $t["bend_deg"], $t["readable"], "lost", "nan", "nan", "nan" }' \
            OFS='\t' "$dir/truth.tsv" >>"$ROWS"
          continue
        fi
        # renderer, set, truth signed yaw, truth bend, readable, status, yaw_deg, signed, bend.
        awk -F'\t' -v r="$renderer" -v s="$set" '
          FNR == 1 { file++ }
          /^#/ { next }
          file == 1 && $1 == "frame" { for (i = 1; i <= NF; i++) t[$i] = i; next }
          file == 1 { yaw[$1] = $t["yaw_signed_deg"]; bend[$1] = $t["bend_deg"]; rd[$1] = $t["readable"]; next }
          file == 2 && $1 == "frame" { for (i = 1; i <= NF; i++) a[$i] = i; next }
          file == 2 { f = $1; print r, s, yaw[f], bend[f], rd[f], $a["status"], $a["yaw_deg"],
                      $a["yaw_signed_deg"], $a["bend_deg"] }' OFS='\t' "$dir/truth.tsv" "$dir/angles.tsv" >>"$ROWS"
      done
    done
  done
  echo "marker-eval: renderers, ${MARKER_EVAL_SET:-heldout} seeds, per-view rows in $ROWS"
  awk -F'\t' '
    function abs(v) { return v < 0 ? -v : v }
    { k = $1 " " $2; n[k]++; rd[k] += $5 }
    $6 == "ok" {
      ok[k]++; e = abs($7 - abs($3)); ys[k] += e
      if ($8 == "nan") nan[k]++
      else { es = abs($8 - $3); if (es > sm[k]) sm[k] = es; if (es > 5) off[k]++ }
      if ($9 != "nan") { bs[k] += abs($9 - $4); bn[k]++ }
    }
    END {
      printf "%-8s %-7s %6s %9s %9s %8s %9s %10s %11s %10s\n", "renderer", "set", "views", "readable",
        "answered", "yaw_mae", "bend_mae", "signed_max", "signed_off5", "signed_nan"
      split("scene rig", rs, " "); split("easy medium hard", ss, " ")
      for (i = 1; i <= 2; i++) for (j = 1; j <= 3; j++) {
        k = rs[i] " " ss[j]; if (!n[k]) continue
        printf "%-8s %-7s %6d %9d %9d %8.2f %9.2f %10.2f %11d %10d\n", rs[i], ss[j], n[k], rd[k], ok[k],
          ok[k] ? ys[k] / ok[k] : 0, bn[k] ? bs[k] / bn[k] : 0, sm[k], off[k], nan[k]
      }
    }' "$ROWS"
  exit 0
fi
read -r -a SYNTH_EXTRA <<<"${MARKER_EVAL_SYNTH:-}"
read -r -a EXTRA <<<"${MARKER_EVAL_FLAGS:-}"

declare -A TIER_FLAGS=(
  [easy]="--background simple --lighting normal"
  [medium]="--background mixed --lighting mixed"
  [hard]="--background mixed --lighting mixed --clutter 8 --noise 3"
)
declare -A TIER_BASE=([easy]=0 [medium]=100 [hard]=200)
case "${MARKER_EVAL_SET:-tuning}" in
  tuning) FIRST=1 ;;
  heldout) FIRST=1001 ;;
  *) echo "marker-eval: MARKER_EVAL_SET must be tuning or heldout" >&2; exit 2 ;;
esac
SEEDS="${MARKER_EVAL_SEEDS:-10}"
if [[ "${MARKER_EVAL_SET:-tuning}" == heldout && "$SEEDS" != 10 ]] || ((SEEDS < 1 || SEEDS > 99)); then
  echo "marker-eval: MARKER_EVAL_SEEDS must be 1..99 (tuning only; held-out has 10)" >&2
  exit 2
fi

# Joins truth.tsv and angles.tsv by frame: tier, scene, frame, truth signed yaw, truth bend,
# readable, upper readable, status, yaw error (signed), bend error.
join_rows() {
  awk -F'\t' -v tier="$1" -v scene="$2" '
    FNR == 1 { file++ }
    /^#/ { next }
    file == 1 && $1 == "frame" { for (i = 1; i <= NF; i++) t[$i] = i; next }
    file == 1 { yaw[$1] = $t["yaw_signed_deg"]; bend[$1] = $t["bend_deg"];
                rd[$1] = $t["readable"]; up[$1] = $t["upper_readable"]; next }
    file == 2 && $1 == "frame" { for (i = 1; i <= NF; i++) a[$i] = i; next }
    file == 2 {
      f = $1; ey = "nan"; eb = "nan"
      if ($a["status"] == "ok") {
        # --thesis writes no signed yaw: its yaw_deg is then scored against |yaw|.
        if ($a["yaw_signed_deg"] == "nan") ey = $a["yaw_deg"] - (yaw[f] < 0 ? -yaw[f] : yaw[f])
        else ey = $a["yaw_signed_deg"] - yaw[f]
        if (ey > 180) ey -= 360; if (ey <= -180) ey += 360
        if ($a["bend_deg"] != "nan") eb = $a["bend_deg"] - bend[f]
      }
      print tier, scene, f, yaw[f], bend[f], rd[f], up[f], $a["status"], ey, eb
    }' OFS='\t' "$3" "$4"
}

ROWS="$WORK/rows.tsv"
: >"$ROWS"
FAILED=0
for tier in easy medium hard; do
  read -r -a FLAGS <<<"${TIER_FLAGS[$tier]}"
  for ((k = 0; k < SEEDS; k++)); do
    seed=$((FIRST + TIER_BASE[$tier] + k))
    for part in wide near; do
      if [[ $part == wide ]]; then views=(--views 24 --max-yaw 135); else views=(--views 6 --max-yaw 5); fi
      dir="$WORK/$tier-$seed-$part"
      if [[ ! -f "$dir/truth.tsv" ]]; then
        "$CLI" -q synth marker "$dir" --seed "$seed" "${views[@]}" "${FLAGS[@]}" "${SYNTH_EXTRA[@]}"
      fi
      if ! "$CLI" -q analyze "$dir/views" -o "$dir/angles.tsv" --engine marker \
        --reference "$dir/reference.png" "${EXTRA[@]}" 2>"$dir/analyze.err"; then
        # A reference the engine refuses: every view of the scene counts as lost.
        echo "marker-eval: $tier seed $seed ($part): $(tail -1 "$dir/analyze.err")" >&2
        FAILED=$((FAILED + 1))
        awk -F'\t' -v tier="$tier" -v scene="$seed-$part" '
          /^#/ { next }
          $1 == "frame" { for (i = 1; i <= NF; i++) t[$i] = i; next }
          { print tier, scene, $1, $t["yaw_signed_deg"], $t["bend_deg"], $t["readable"],
                  $t["upper_readable"], "lost", "nan", "nan" }' OFS='\t' "$dir/truth.tsv" >>"$ROWS"
        continue
      fi
      join_rows "$tier" "$seed-$part" "$dir/truth.tsv" "$dir/angles.tsv" >>"$ROWS"
    done
  done
done

echo "marker-eval: ${MARKER_EVAL_SET:-tuning} set, per-view rows in $ROWS;" \
  "$FAILED scene(s) refused by the engine (their views count as lost)"
awk -F'\t' '
  function abs(v) { return v < 0 ? -v : v }
  { tier = $1; n[tier]++ }
  $6 == 1 { rd[tier]++; if ($8 == "ok") ans[tier]++ }
  $6 == 0 { un[tier]++; if ($8 == "ok") un_ok[tier]++ }
  $8 == "ok" && $6 == 1 {
    e = abs($9); ys[tier] += e; yb[tier] += $9; yn[tier]++; if (e > ym[tier]) ym[tier] = e
    if (abs($4) <= 5) { zn[tier]++; if (e > zm[tier]) zm[tier] = e }
    if ($10 != "nan") { b = abs($10); bs[tier] += b; bn[tier]++; if (b > bm[tier]) bm[tier] = b }
    if ($7 == 1) { upn[tier]++; if ($10 != "nan") upb[tier]++ }
    if (e > 15 || ($10 != "nan" && abs($10) > 15)) wrong[tier]++
  }
  abs($4) <= 5 && $6 == 1 { z_all[tier]++ }
  END {
    printf "%-7s %6s %9s %9s %8s %8s %8s %9s %8s %8s %9s %7s\n", "tier", "views",
      "readable", "answered", "yaw_mae", "yaw_max", "yaw_bias", "near0_max", "bend_mae",
      "bend_max", "bend_read", "wrong"
    split("easy medium hard", order, " ")
    for (i = 1; i <= 3; i++) {
      t = order[i]
      if (!n[t]) continue
      printf "%-7s %6d %9d %8.1f%% %8.2f %8.2f %+8.2f %6.2f/%-2d %8.2f %8.2f %8.1f%% %7d\n", t, n[t],
        rd[t], 100 * ans[t] / rd[t], ys[t] / yn[t], ym[t], yb[t] / yn[t], zm[t], zn[t],
        bn[t] ? bs[t] / bn[t] : 0, bm[t], upn[t] ? 100 * upb[t] / upn[t] : 0, wrong[t]
      printf "        unreadable views: %d, answered: %d; near-zero views answered %d of %d\n",
        un[t], un_ok[t], zn[t], z_all[t]
    }
  }' "$ROWS"
