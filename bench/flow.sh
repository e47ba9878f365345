#!/usr/bin/env bash
# FLOWPAK benchmark (thesis ch. 3, issue 6): the bundled examples, and the koi at a density
# that gives about 50 elements, the size of the thesis's hour-long run (15 refinement
# iterations). One CSV row per scene with the median wall time and the time of each phase
# (from the median run), element count, iterations, fill, overlaps and folded elements (the
# last column, from 2026-12-04 on); rows go to
# bench/flow-results.csv. Target (issue 6): ≤ 60 s for the 50-element scene.
set -euo pipefail
source "$(dirname "$0")/common.sh"
csv=bench/flow-results.csv
header="date,commit,scene,elements,streamlines,iterations,wall_s_median,field_s,streamlines_s,blobs_s,placement_s,refinement_s,fill_art,overlaps,outside,accepted_of_tried,folded"
bench_csv "$csv" "$header"
scenes=("koi|examples/flow/koi.svg"
        "medallion|examples/flow/medallion.svg"
        "owl|examples/flow/owl.svg --mirror x=300"
        "koi-50|examples/flow/koi.svg --gap 30 --min-length 45 --max-length 180")
for entry in "${scenes[@]}"; do
  name=${entry%%|*}
  args=${entry#*|}
  walls=()
  for run in $(seq "$runs"); do
    # shellcheck disable=SC2086
    "$pak" flow $args -e examples/flow/elements -o "$work/flow-$name.svg" --png "$work/flow-$name.png" \
      --report "$work/flow-$name-$run.json" --quiet
    walls+=("$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds"]["wall"])' "$work/flow-$name-$run.json")")
  done
  wall=$(median "${walls[@]}")
  # The phases of the run whose wall time is the median.
  pick=1
  for run in $(seq "$runs"); do
    [ "$(median "${walls[$((run - 1))]}")" = "$wall" ] && pick=$run
  done
  row=$(python3 - "$work/flow-$name-$pick.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
s = r["seconds"]
print(",".join(str(v) for v in [
    r["element-count"], r["streamline-count"], r["iterations"]] + [f"{s[k]:.3f}" for k in
    ("field", "streamlines", "blobs", "placement", "refinement")] + [
    f"{r['fill-ratio-art']:.4f}", r["overlap-count"], r["elements-outside"],
    f"{r['placements-accepted']}/{r['placements-tried']}", r["self-intersecting-outlines"]]))
PY
)
  echo "$stamp,$commit,$name,$(echo "$row" | cut -d, -f1-3),$wall,$(echo "$row" | cut -d, -f4-)" | tee -a "$csv"
done
