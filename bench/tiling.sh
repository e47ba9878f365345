#!/usr/bin/env bash
# Tileable packing benchmark (thesis 4.8, docs/tiling.md): each tile scene runs BENCH_RUNS
# times (default 3); one CSV row per scene with the median wall and simulation times, the
# iterations (exact: a seed reproduces a run), the fill ratios over the tile's area and the
# overlaps found on the torus (seams included). Rows go to bench/tiling-results.csv.
set -euo pipefail
source "$(dirname "$0")/common.sh"
threads=${BENCH_THREADS:-2}
csv=bench/tiling-results.csv
header="date,commit,scene,threads,elements,vertices,iterations,wall_s_median,simulation_s_median,fill_art,fill_skin,overlaps"

scenes=("example-tile|--tile 1000,1000 --elements examples/elements --count 20 --seed 7")
if [ -d "$data/repulsionpak/animals" ]; then
  scenes+=("animals-tile|--tile 1000,1000 --elements $data/repulsionpak/animals --count 27 --seed 2")
else
  echo "bench: $data not found; running the bundled example only" >&2
fi

bench_csv "$csv" "$header"
for entry in "${scenes[@]}"; do
  name=${entry%%|*}
  args=${entry#*|}
  walls=()
  sims=()
  for run in $(seq "$runs"); do
    # shellcheck disable=SC2086
    "$pak" pack $args -o "$work/$name.svg" --tile-preview "$work/$name-3x3.png" --threads "$threads" \
      --report "$work/$name.json" --quiet
    walls+=("$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall-seconds"])' "$work/$name.json")")
    sims+=("$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["simulation-seconds"])' "$work/$name.json")")
  done
  row=$(python3 - "$work/$name.json" "${walls[*]}" "${sims[*]}" <<'PY'
import json, statistics, sys
report = json.load(open(sys.argv[1]))
wall = statistics.median(float(w) for w in sys.argv[2].split())
sim = statistics.median(float(w) for w in sys.argv[3].split())
print(",".join(str(v) for v in [
    report["element-count"], report["vertex-count"], report["iterations"], f"{wall:.3f}", f"{sim:.3f}",
    f"{report['fill-ratio-art']:.4f}", f"{report['fill-ratio-skin']:.4f}", report["overlap-count"]]))
PY
)
  echo "$stamp,$commit,$name,$threads,$row" | tee -a "$csv"
done
