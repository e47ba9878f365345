#!/usr/bin/env bash
# The time-spring trade-off of thesis Fig. 5.21 (issue 15, item 2): tightness against
# smoothness over a range of --time-springs, on the stars example (and the chase with
# ANIMATE_SCENES="stars chase"), seeds 1–3, 100 frames, 2 threads. The edge springs are 20
# (--k-edge); the thesis's ratio of time to edge springs, 0.01 / 10, is --time-springs 0.02.
# Per run: negative space and P2 (median over 10 frames), the mean centroid acceleration of
# the unguided elements (canonical units per frame², report `mean-centroid-acceleration`),
# frames with an overlap, iterations and simulation seconds. Rows go to
# bench/animate-time-springs-results.csv; a summary (median over seeds) follows.
#   ANIMATE_SEEDS="1" TIME_SPRINGS="0.02 4" bench/animate-time-springs.sh build/release
set -euo pipefail
source "$(dirname "$0")/common.sh"
seeds=${ANIMATE_SEEDS:-1 2 3}
names=${ANIMATE_SCENES:-stars}
strengths=${TIME_SPRINGS:-0.02 0.2 1 4 20}
csv=bench/animate-time-springs-results.csv
header="date,commit,scene,seed,time_springs,iterations,stop,neg_median,P2_median,P2_worst,mean_centroid_acceleration,frames_with_overlaps,sim_s"
declare -A scenes
scenes[stars]="-c examples/animate/stars/disc.svg -a examples/animate/stars/stars.json"
scenes[chase]="-c examples/animate/chase/annulus.svg -a examples/animate/chase/chase.json"

bench_csv "$csv" "$header"
rows=()
for name in $names; do
  for k in $strengths; do
    for seed in $seeds; do
      out="$work/animate-springs-$name-k$k-s$seed"
      # shellcheck disable=SC2086
      "$pak" animate ${scenes[$name]} --seed "$seed" --threads 2 --frames 100 --time-springs "$k" -o "$out" --no-gif \
        --report "$out.json" --quiet
      line="$stamp,$commit,$(python3 - "$out.json" "$name" "$seed" "$k" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
e = r["evenness-over-frames"]
print(",".join(str(v) for v in [sys.argv[2], sys.argv[3], sys.argv[4], r["iterations"], r["stop-reason"],
      f'{e["negative-ratio-median"]:.3f}', f'{e["P2-median"]:.3f}', f'{e["P2-worst"]:.3f}',
      f'{r["mean-centroid-acceleration"]:.4f}', r["frames-with-overlaps"], f'{r["seconds"]["simulation"]:.1f}']))
PY
)"
      echo "$line" | tee -a "$csv"
      rows+=("$line")
    done
  done
done
echo
echo "summary (median over seeds):"
printf '%s\n' "${rows[@]}" | PYTHONPATH="$(dirname "$0")" python3 -c '
import statistics
from rows import grouped, column
for (scene, k), rs in grouped():
    med = lambda i: statistics.median(column(rs, i))
    print(f"{scene} --time-springs {k}, {len(rs)} seeds: negative space {med(7):.3f}, P2 {med(8):.3f}, "
          f"centroid acceleration {med(10):.4f}, iterations {med(5):.0f}, simulation {med(12):.1f} s")
'
