#!/usr/bin/env bash
# AnimationPak benchmark (thesis ch. 5, issue 7): the two bundled examples, and a 32-element
# version of the stars scene with 100 slices — the size of the thesis's Table 5.1 scenes
# (target: ≥ 30 elements, ≥ 50,000 vertices, ≤ 10 minutes, ≤ 2 GB). Each scene runs with 1 and
# 2 threads (the result is the same; the time shows the scaling). Rows go to
# bench/animate-results.csv: vertices, springs, iterations, simulation seconds (median),
# seconds per iteration, peak memory, fill, frames with overlaps. ANIMATE_SCENES (names) and
# ANIMATE_THREADS (default "1 2") pick a part of it.
set -euo pipefail
source "$(dirname "$0")/common.sh"
csv=bench/animate-results.csv
header="date,commit,scene,threads,elements,vertices,springs,envelope_triangles,slices,iterations,stop,sim_s_median,s_per_iteration,render_s,peak_rss_mb,art_fill,frames_with_overlaps,frames"
bench_csv "$csv" "$header"
big="$work/stars-32.json"
python3 - "$big" <<'PY'
import json, sys
s = json.load(open("examples/animate/stars/stars.json"))
for e in s["elements"]:
    e["svg"] = "../../examples/animate/stars/" + e["svg"]
    e["count"] = 6 if e["count"] >= 4 else 5
json.dump(s, open(sys.argv[1], "w"), indent=1)
PY
scenes=("stars|examples/animate/stars/disc.svg|examples/animate/stars/stars.json"
        "chase|examples/animate/chase/annulus.svg|examples/animate/chase/chase.json"
        "stars-32|examples/animate/stars/disc.svg|$big")
for entry in "${scenes[@]}"; do
  IFS='|' read -r name container animation <<< "$entry"
  [[ " ${ANIMATE_SCENES:-stars chase stars-32} " == *" $name "* ]] || continue
  for threads in ${ANIMATE_THREADS:-1 2}; do
    sims=()
    for run in $(seq "$runs"); do
      report="$work/animate-$name-$threads-$run.json"
      /usr/bin/time -f "%M" -o "$work/animate-rss" "$pak" animate -c "$container" -a "$animation" \
        -o "$work/animate-$name" --threads "$threads" --frames 100 --report "$report" --quiet
      rss=$(( $(cat "$work/animate-rss") / 1024 ))
      sims+=("$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds"]["simulation"])' "$report")")
    done
    row=$(python3 - "$report" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(",".join(str(v) for v in [r["elements"], r["vertices"], r["springs"], r["envelope-triangles"], r["slices"],
      r["iterations"], r["stop-reason"]]))
print(f'{r["seconds-per-iteration"]:.4f},{r["seconds"]["rendering"]:.2f}')
print(f'{r["art-fill-mean-over-frames"]:.4f},{r["frames-with-overlaps"]},{r["parameters"]["frames"]}')
PY
)
    first=$(echo "$row" | sed -n 1p); second=$(echo "$row" | sed -n 2p); third=$(echo "$row" | sed -n 3p)
    echo "$stamp,$commit,$name,$threads,$first,$(median "${sims[@]}"),$second,$rss,$third" | tee -a "$csv"
  done
done
