#!/usr/bin/env bash
# AnimationPak quality benchmark (issue 15): both examples and the crowd (stars with a guided
# comet crossing them), seeds 1–5, at 100 and at 500 frames, 2 threads. Each seed is simulated once: the 500-frame run resumes from the 100-frame
# run's last checkpoint (bit-identical, docs/animationpak.md), so only the frames differ.
# Per run: frames with an overlap, with an element outside and with a self-crossing outline,
# slices unfolded, frames separated, the evenness of 10 frames (median and worst P2, median
# negative space), the guided growth ratio, iterations and simulation seconds. Rows go to
# bench/animate-quality-results.csv; a summary per scene and frame count follows.
#   ANIMATE_SEEDS="1 2" bench/animate-quality.sh build/release   # fewer seeds
#   ANIMATE_SCENES="stars" …                                      # one example
#   ANIMATE_RENDER_ONLY=1 …   # resume both from an earlier run's checkpoints: the frames again
#                             # (after a change to what follows the simulation), sim_s ≈ 0
set -euo pipefail
source "$(dirname "$0")/common.sh"
seeds=${ANIMATE_SEEDS:-1 2 3 4 5}
names=${ANIMATE_SCENES:-stars chase crowd}
csv=bench/animate-quality-results.csv
header="date,commit,scene,seed,frames,iterations,stop,frames_with_overlaps,frames_outside,frames_self_crossing,unfolded_slices,frames_separated,neg_median,P2_median,P2_worst,guided_growth_ratio,sim_s"
declare -A scenes
scenes[stars]="-c examples/animate/stars/disc.svg -a examples/animate/stars/stars.json"
scenes[chase]="-c examples/animate/chase/annulus.svg -a examples/animate/chase/chase.json"
scenes[crowd]="-c examples/animate/stars/disc.svg -a examples/animate/stars/crowd.json"

row() {  # row REPORT SCENE SEED FRAMES
  python3 - "$@" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
e = r["evenness-over-frames"]
print(",".join(str(v) for v in [sys.argv[2], sys.argv[3], sys.argv[4], r["iterations"], r["stop-reason"],
      r["frames-with-overlaps"], r["frames-with-element-outside"], r["frames-with-self-intersecting-outline"],
      r["unfolded-slices"], r["frames-separated"], f'{e["negative-ratio-median"]:.3f}', f'{e["P2-median"]:.3f}',
      f'{e["P2-worst"]:.3f}', f'{r["guided-growth-ratio"]:.3f}', f'{r["seconds"]["simulation"]:.1f}']))
PY
}

bench_csv "$csv" "$header"
rows=()
for name in $names; do
  for seed in $seeds; do
    out="$work/animate-quality-$name-s$seed"
    # shellcheck disable=SC2086
    simulate=(--checkpoint "$out.checkpoint" --every 50)
    [ -n "${ANIMATE_RENDER_ONLY:-}" ] && simulate=(--resume "$out.checkpoint")
    "$pak" animate ${scenes[$name]} --seed "$seed" --threads 2 --frames 100 -o "$out-f100" --no-gif \
      "${simulate[@]}" --report "$out-f100.json" --quiet
    line="$stamp,$commit,$(row "$out-f100.json" "$name" "$seed" 100)"
    echo "$line" | tee -a "$csv"
    rows+=("$line")
    # shellcheck disable=SC2086
    "$pak" animate ${scenes[$name]} --seed "$seed" --threads 2 --frames 500 -o "$out-f500" --no-gif \
      --resume "$out.checkpoint" --report "$out-f500.json" --quiet
    line="$stamp,$commit,$(row "$out-f500.json" "$name" "$seed" 500)"
    echo "$line" | tee -a "$csv"
    rows+=("$line")
  done
done
echo
echo "summary (median over seeds; worst in brackets; counts are worst):"
printf '%s\n' "${rows[@]}" | PYTHONPATH="$(dirname "$0")" python3 -c '
import statistics
from rows import grouped, column
for (scene, frames), rs in grouped():
    col = lambda i: column(rs, i)
    print(f"{scene} {frames} frames, {len(rs)} seeds: overlaps {max(col(7)):.0f}, outside {max(col(8)):.0f}, "
          f"self-crossing {max(col(9)):.0f}, negative space {statistics.median(col(12)):.3f} ({max(col(12)):.3f}), "
          f"P2 {statistics.median(col(13)):.3f} ({max(col(14)):.3f}), guided {min(col(15)):.3f} (smallest), "
          f"simulation {statistics.median(col(16)):.1f} s")
'
