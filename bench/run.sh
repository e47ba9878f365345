#!/usr/bin/env bash
# Whole-run benchmarks for `make bench`: every scene runs BENCH_RUNS times (default 3) per
# thread count; one CSV row per scene and thread count with the median wall time, appended to
# bench/results.csv and printed. Iteration counts are exact (a seed reproduces a run).
set -euo pipefail
source "$(dirname "$0")/common.sh"
csv=bench/results.csv
header="date,commit,scene,threads,elements,vertices,iterations,wall_s_median,simulation_s_median,s_per_1000_iterations,fill_art,fill_skin,overlaps,peak_rss_mb"

scenes=("example|--container examples/scene.svg --elements examples/elements")
if [ -d "$data/repulsionpak" ]; then
  scenes+=("animals-heart|--container $data/repulsionpak/containers/heart.path --elements $data/repulsionpak/animals --count 27")
  scenes+=("mdi-heart|--container $data/mdi/heart.svg --elements $data/mdi/cat.svg $data/mdi/dog.svg $data/mdi/rabbit.svg $data/mdi/bird.svg $data/mdi/fish.svg $data/mdi/penguin.svg $data/mdi/turtle.svg $data/mdi/snail.svg")
else
  echo "bench: $data not found; running the bundled example only" >&2
fi

bench_csv "$csv" "$header"
for entry in "${scenes[@]}"; do
  name=${entry%%|*}
  args=${entry#*|}
  for threads in 1 2; do
    walls=()
    sims=()
    for run in $(seq "$runs"); do
      # shellcheck disable=SC2086
      /usr/bin/time -f "%M" -o "$work/rss.txt" "$pak" pack $args -o "$work/$name.svg" --png "$work/$name.png" \
        --threads "$threads" --report "$work/$name.json" --quiet
      walls+=("$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall-seconds"])' "$work/$name.json")")
      sims+=("$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["simulation-seconds"])' "$work/$name.json")")
    done
    row=$(python3 - "$work/$name.json" "$work/rss.txt" "${walls[*]}" "${sims[*]}" <<'PY'
import json, statistics, sys
report = json.load(open(sys.argv[1]))
rss_kb = int(open(sys.argv[2]).read().split()[-1])
wall = statistics.median(float(w) for w in sys.argv[3].split())
sim = statistics.median(float(w) for w in sys.argv[4].split())
it = report["iterations"]
print(",".join(str(v) for v in [
    report["element-count"], report["vertex-count"], it, f"{wall:.3f}", f"{sim:.3f}",
    f"{1000 * sim / max(it, 1):.4f}", f"{report['fill-ratio-art']:.4f}", f"{report['fill-ratio-skin']:.4f}",
    report["overlap-count"], f"{rss_kb / 1024:.1f}"]))
PY
)
    line="$stamp,$commit,$name,$threads,$row"
    echo "$line" | tee -a "$csv"
  done
done

# Metrics: all three curves (100 radii, 1000 × 1000 grid) of each packing written above.
mcsv=bench/metrics-results.csv
mheader="date,commit,packing,elements,radii,grid,wall_s_median"
bench_csv "$mcsv" "$mheader"
for entry in "${scenes[@]}"; do
  name=${entry%%|*}
  walls=()
  for run in $(seq "$runs"); do
    start=$(date +%s.%N)
    "$pak" metrics "$work/$name.svg" --report "$work/$name.json" --radii 100 --grid 1000 --json "$work/$name-metrics.json" > /dev/null
    walls+=("$(python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$(date +%s.%N)")")
  done
  elements=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["element-count"])' "$work/$name.json")
  wall=$(python3 -c 'import statistics,sys; print(f"{statistics.median(float(w) for w in sys.argv[1:]):.3f}")' "${walls[@]}")
  echo "$stamp,$commit,$name,$elements,100,1000,$wall" | tee -a "$mcsv"
done

# The issue-5 features and FLOWPAK: each script appends its own CSV (bench/*-results.csv) and prints it.
for extra in quality.sh secondary.sh tiling.sh shape_matching.sh containers-orientation.sh flow.sh animate.sh animate-quality.sh animate-time-springs.sh; do
  echo
  echo "== bench/$extra"
  ./bench/"$extra" "$build"
done
