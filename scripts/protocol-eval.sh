#!/usr/bin/env bash
# The thesis protocol, scored scene by scene (docs/synth.md, "Scoring the thesis protocol"):
# renders arm scenes with a generator (`synth arm --random` or `--generator capsule`), runs each
# engine through `armmimic-cli analyze` as an operator would, scores every angle file against
# the scene's truth over its motion frames and prints one row per scene and run, then a table of
# every generator, run and tier like issue 28's.
#
#   scripts/protocol-eval.sh [--build DIR] [--work DIR] [--generators random,capsule]
#       [--tiers medium,hard] [--set heldout|tuning|unit] [--first-seed S] [--scenes N]
#       [--runs bgsub,lk,lk+joints] [--size WxH] [--param ENGINE.KEY=VALUE]...
#
# Runs: ENGINE runs the thesis protocol without clicks (--background BG --arm-length AL --start K
# --standstill-frames M; an engine that does not take --arm-length runs without it), and
# ENGINE+joints gives the shoulder, elbow and wrist of the truth at frame K instead (as clicked
# at the start frame). `pose` runs the pose engine as an operator would: the moving arm named
# (--side: the person's own, so the image's right arm is their left) and --start K; `blazepose`
# runs it the same way with --network blazepose. K and M are the scene's own (45 and 60 in
# capsule scenes). `--param` goes to every run whose engine takes it (hybrid takes lk.* and
# bgsub.* too); give a run with other parameters its own --work.
# Seeds: the set's range of each generator (held out unless --set tuning): random 100000-,
# capsule 300000-; tuning 1000- and 3000-; unit 8000- of both (the unit tests' scenes, free to
# look at). Held-out scenes are for measuring only: nothing may
# be tuned on them. Scenes and angle files already in the work folder are reused.
# Writes WORK/scenes.tsv (one row per scene and run) and WORK/table.md (the summary).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=build
WORK=""
GENERATORS=random,capsule
TIERS=medium,hard
SET=heldout
FIRST=""
SCENES=8
RUNS=bgsub,lk,lk+joints
SIZE=320x240
PARAMS=()
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
while (($# > 0)); do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    --work) WORK="$2"; shift 2 ;;
    --generators) GENERATORS="$2"; shift 2 ;;
    --tiers) TIERS="$2"; shift 2 ;;
    --set) SET="$2"; shift 2 ;;
    --first-seed) FIRST="$2"; shift 2 ;;
    --scenes) SCENES="$2"; shift 2 ;;
    --runs) RUNS="$2"; shift 2 ;;
    --size) SIZE="$2"; shift 2 ;;
    --param) PARAMS+=("$2"); shift 2 ;;
    -h | --help) usage; exit 0 ;;
    *) echo "protocol-eval: unknown option '$1' (try --help)" >&2; exit 2 ;;
  esac
done
CLI="$BUILD/bin/armmimic-cli"
[[ -x "$CLI" ]] || { echo "protocol-eval: $CLI not found; build first (scripts/build.sh $BUILD)" >&2; exit 2; }
[[ "$SET" == heldout || "$SET" == tuning || "$SET" == unit ]] || { echo "protocol-eval: --set '$SET' is not heldout, tuning or unit" >&2; exit 2; }
[[ "$SCENES" =~ ^[0-9]+$ && "$SCENES" -ge 1 ]] || { echo "protocol-eval: --scenes '$SCENES' is not a positive number" >&2; exit 2; }
WORK="${WORK:-$(mktemp -d /tmp/armmimic-protocol-XXXXXX)}"
mkdir -p "$WORK"
IFS=, read -r -a GENS <<<"$GENERATORS"
IFS=, read -r -a TIER_LIST <<<"$TIERS"
IFS=, read -r -a RUN_LIST <<<"$RUNS"

# The seed range of a generator and set: "first last".
seed_range() {
  case "$1:$SET" in
    random:heldout) echo "100000 100999" ;;
    random:tuning) echo "1000 1999" ;;
    capsule:heldout) echo "300000 300999" ;;
    capsule:tuning) echo "3000 3999" ;;
    *:unit) echo "8000 8999" ;;
  esac
}

meta() { sed -n '2p' "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }

# Scores ANGLES against TRUTH over the frames from FIRST on. Prints
# "motion ok coverage median p90 max mean cw_share yaw_mean yaw_frames" (errors in degrees: per
# frame the mean of the upper arm's and the forearm's wrapped direction errors; cw: ok frames
# whose worse segment is more than 15 degrees off, over the motion frames; yaw: the mean
# |yaw_deg error| over the ok frames of a straight arm (truth |bend| < 5) that have a yaw).
score() {
  awk -F'\t' -v first="$3" '
    function wrap(d) { d = d - 360 * int((d + 180) / 360); if (d < -180) d += 360; return d < 0 ? -d : d }
    function q(p,   pos, lo) { if (n == 0) return "nan"; pos = p * (n - 1); lo = int(pos);
      return lo + 1 < n ? e[lo] + (pos - lo) * (e[lo + 1] - e[lo]) : e[lo] }
    FNR == 1 { file++ }
    /^#/ || $1 == "frame" { next }
    file == 1 && $1 >= first && $3 != "nan" && $4 != "nan" {
      tu[$1] = $3; tf[$1] = $4; ty[$1] = $5; straight[$1] = ($6 < 5 && $6 > -5); motion++
    }
    file == 2 && ($1 in tu) && $3 == "ok" && $4 != "nan" && $5 != "nan" {
      a = wrap($4 - tu[$1]); b = wrap($5 - tf[$1])
      e[n++] = (a + b) / 2; sum += (a + b) / 2
      if ((a > b ? a : b) > 15) cw++
      if (straight[$1] && $6 != "nan" && ty[$1] != "nan") { y = $6 - ty[$1]; ysum += y < 0 ? -y : y; yn++ }
    }
    END {
      for (i = 1; i < n; i++) { v = e[i]; for (j = i - 1; j >= 0 && e[j] > v; j--) e[j + 1] = e[j]; e[j + 1] = v }
      printf "%d %d %.4f %s %s %s %s %.4f %s %d\n", motion, n, motion ? n / motion : 0, q(0.5),
        q(0.9), n ? e[n - 1] : "nan", n ? sum / n : "nan", motion ? cw / motion : 0,
        yn ? ysum / yn : "nan", yn
    }' "$1" "$2"
}

for gen in "${GENS[@]}"; do
  [[ "$gen" == random || "$gen" == capsule ]] || { echo "protocol-eval: unknown generator '$gen' (random or capsule)" >&2; exit 2; }
  read -r lo hi <<<"$(seed_range "$gen")"
  first_seed="${FIRST:-$lo}"
  if ((first_seed < lo || first_seed + SCENES - 1 > hi)); then
    echo "protocol-eval: seeds $first_seed..$((first_seed + SCENES - 1)) leave the $SET range $lo-$hi of $gen" >&2
    exit 2
  fi
done

SCENES_TSV="$WORK/scenes.tsv"
printf 'generator\ttier\tseed\trun\texit\tseconds\tmotion_frames\tok_frames\tcoverage\tmedian_deg\tp90_deg\tmax_deg\tmean_deg\tconfidently_wrong\tyaw_straight_deg\tyaw_straight_frames\n' >"$SCENES_TSV"
printf '| generator | run | tier | seed | coverage | median | p90 | max | confidently wrong |\n|---|---|---|---|---|---|---|---|---|\n'
for gen in "${GENS[@]}"; do
  read -r lo hi <<<"$(seed_range "$gen")"
  first_seed="${FIRST:-$lo}"
  for tier in "${TIER_LIST[@]}"; do
    for ((seed = first_seed; seed < first_seed + SCENES; seed++)); do
      dir="$WORK/$gen-$tier-$seed"
      if [[ ! -f "$dir/scene.avi" || ! -f "$dir/truth.tsv" ]]; then
        if [[ "$gen" == random ]]; then gflag=(--random); else gflag=(--generator "$gen"); fi
        "$CLI" -q synth arm "$dir" "${gflag[@]}" --tier "$tier" --seed "$seed" --size "$SIZE"
      fi
      k=$(meta "$dir/truth.tsv" background_frames)
      m=$(meta "$dir/truth.tsv" standstill_frames)
      read -r sx sy ex ey wx wy <<<"$(awk -F'\t' -v f="$k" '$1 == f { print $7, $8, $9, $10, $11, $12 }' "$dir/truth.tsv")"
      for run in "${RUN_LIST[@]}"; do
        engine="${run%+joints}"
        out="$dir/$run.tsv"
        if [[ "$run" == pose || "$run" == blazepose ]]; then
          [[ "$(meta "$dir/truth.tsv" side)" == right ]] && pside=left || pside=right
          flags=(--side "$pside" --start "$k")
          if [[ "$run" == blazepose ]]; then
            engine=pose
            flags+=(--network blazepose)
          fi
        elif [[ "$run" == *+joints ]]; then
          flags=(--shoulder "$sx,$sy" --elbow "$ex,$ey" --wrist "$wx,$wy" --start "$k")
        else
          flags=(--background "$dir/background.png" --arm-length "$dir/armlength.png" --start "$k" --standstill-frames "$m")
        fi
        for assignment in "${PARAMS[@]}"; do
          prefix="${assignment%%.*}"
          if [[ "$prefix" == "$engine" || ("$engine" == hybrid && ("$prefix" == lk || "$prefix" == bgsub)) ]]; then
            flags+=(--param "$assignment")
          fi
        done
        code=0
        seconds=0
        if [[ ! -f "$out" ]]; then
          t0=$(date +%s.%N)
          # Not quiet: RUN.err keeps the run's estimates and its end-of-run summary, with the
          # most frequent reasons rows were lost (what to read first when a scene is bad).
          "$CLI" --no-progress analyze "$dir/scene.avi" -o "$out" --engine "$engine" "${flags[@]}" 2>"$dir/$run.err" || code=$?
          if ((code == 2)) && grep -q -- '--arm-length' "$dir/$run.err"; then
            code=0
            "$CLI" --no-progress analyze "$dir/scene.avi" -o "$out" --engine "$engine" "${flags[@]:0:2}" "${flags[@]:4}" 2>"$dir/$run.err" || code=$?
          fi
          seconds=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
        fi
        if [[ -f "$out" ]]; then
          read -r motion ok cov med p90 max mean cw yaw yawn <<<"$(score "$dir/truth.tsv" "$out" $((k + m)))"
        else
          read -r motion ok cov med p90 max mean cw yaw yawn <<<"0 0 0 nan nan nan nan 0 nan 0"
        fi
        printf '%s\t%s\t%s\t%s\t%s\t%.1f\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$gen" "$tier" "$seed" \
          "$run" "$code" "$seconds" "$motion" "$ok" "$cov" "$med" "$p90" "$max" "$mean" "$cw" "$yaw" \
          "$yawn" >>"$SCENES_TSV"
        awk -v g="$gen" -v r="$run" -v t="$tier" -v s="$seed" -v c="$cov" -v a="$med" -v b="$p90" \
          -v x="$max" -v w="$cw" -v code="$code" 'function d(v) { return v == "nan" ? "-" : sprintf("%.1f°", v) }
          BEGIN { printf "| %s | %s | %s | %s | %.1f %% | %s | %s | %s | %.1f %%%s |\n", g, r, t, s, 100 * c,
            d(a), d(b), d(x), 100 * w, code != 0 ? " (exit " code ")" : "" }'
      done
    done
  done
done

# The summary: per generator, run and tier, the distribution over scenes of each scene's mean
# error (median, p90, max, as issue 28's table), the worst scene's median and p90 of its frames,
# the pooled coverage and confidently wrong share, and the scenes with no ok frame.
awk -F'\t' '
  function quant(list, p,   n, v, i, j, x, pos, lo) {
    n = split(list, v, " "); if (list == "") return "-"
    for (i = 2; i <= n; i++) { x = v[i] + 0; for (j = i - 1; j >= 1 && v[j] + 0 > x; j--) v[j + 1] = v[j]; v[j + 1] = x }
    pos = 1 + p * (n - 1); lo = int(pos)
    return sprintf("%.1f°", lo < n ? v[lo] + (pos - lo) * (v[lo + 1] - v[lo]) : v[lo]) }
  NR == 1 { next }
  {
    key = $1 "\t" $4 "\t" $2
    if (!(key in scenes)) order[++keys] = key
    scenes[key]++; motion[key] += $7; ok[key] += $8; cwf[key] += $14 * $7
    if ($8 == 0) empty[key]++
    if ($13 != "nan") { means[key] = means[key] " " $13; if ($10 > wmed[key]) wmed[key] = $10; if ($11 > wp90[key]) wp90[key] = $11 }
    if (!(key in wcov) || $9 < wcov[key]) wcov[key] = $9
    if ($16 > 0) { ysum[key] += $15 * $16; yn[key] += $16 }
  }
  END {
    print "| generator | run | tier | scenes | median | p90 | max | worst scene median | worst scene p90 | coverage | worst coverage | confidently wrong | no output | yaw, straight arm |"
    print "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    for (i = 1; i <= keys; i++) {
      k = order[i]; split(k, f, "\t"); m = substr(means[k], 2)
      printf "| %s | %s | %s | %d | %s | %s | %s | %.1f° | %.1f° | %.1f %% | %.1f %% | %.1f %% | %d | %s |\n",
        f[1], f[2], f[3], scenes[k], quant(m, 0.5), quant(m, 0.9), quant(m, 1), wmed[k], wp90[k],
        100 * ok[k] / motion[k], 100 * wcov[k], 100 * cwf[k] / motion[k], empty[k] + 0,
        yn[k] ? sprintf("%.1f° (%d frames)", ysum[k] / yn[k], yn[k]) : "-"
    }
  }' "$SCENES_TSV" >"$WORK/table.md"
echo
cat "$WORK/table.md"
echo "protocol-eval: $SCENES_TSV, $WORK/table.md" >&2
