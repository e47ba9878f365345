#!/usr/bin/env bash
# RepulsionPak quality benchmark (issue 14): five scenes, seeds 1–10, default options, 2 threads.
# Per scene: median and worst negative space, pocket share P2, overlaps, elements outside,
# self-crossing outlines, iterations and wall time, and the primaries' area spread (CV). Rows
# are appended to bench/quality-results.csv and printed; seed 1 of every scene goes on a contact
# sheet, out/bench/quality-sheet.png, to look at.
#   QUALITY_SEEDS="1 2 3" bench/quality.sh build/release   # fewer seeds for a quick look
#   QUALITY_SCENES="a b" …                                # some scenes only
#   QUALITY_ARGS="--overlap-tolerance 0" …                # extra pack options for every run
set -euo pipefail
source "$(dirname "$0")/common.sh"
seeds=${QUALITY_SEEDS:-$(seq -s " " 1 10)}
extra=${QUALITY_ARGS:-}
csv=bench/quality-results.csv
header="date,commit,scene,seeds,args,neg_median,neg_worst,P2_median,P2_worst,overlaps_worst,outside_worst,self_crossing_worst,iterations_median,wall_s_median,wall_s_worst,area_cv_median"

declare -A scenes
scenes[d]="--container examples/scene.svg --elements examples/elements"
scenes[e]="--container examples/long/pond.svg --elements examples/long/elements"
if [ -d "$data/repulsionpak" ]; then
  animals="--container $data/repulsionpak/containers/heart.path --elements $data/repulsionpak/animals --count 25"
  scenes[a]="$animals"
  scenes[b]="$animals --secondary $data/repulsionpak/small_cat"
  mdi=""
  for n in cat dog rabbit bird fish penguin turtle snail; do mdi+=" $data/mdi/$n.svg"; done
  scenes[c]="--container $data/mdi/heart.svg --elements$mdi"
else
  echo "bench/quality: $data not found; scenes a, b and c skipped" >&2
fi
names=${QUALITY_SCENES:-a b c d e}

bench_csv "$csv" "$header"
sheet=()
for name in $names; do
  [ -n "${scenes[$name]:-}" ] || continue
  reports=()
  for seed in $seeds; do
    out="$work/quality-$name-s$seed"
    # shellcheck disable=SC2086
    "$pak" pack ${scenes[$name]} $extra --seed "$seed" --threads 2 -o "$out.svg" --report "$out.json" --quiet
    reports+=("$out.json")
  done
  first=$(echo "$seeds" | awk '{print $1}')
  "$pak" render "$work/quality-$name-s$first.svg" -o "$work/quality-$name.png" --width 500
  sheet+=("$name:$work/quality-$name-s$first.svg")
  row=$(python3 - "${reports[@]}" <<'PY'
import json, statistics, sys
rows = [json.load(open(f)) for f in sys.argv[1:]]
def col(f): return [f(r) for r in rows]
neg = col(lambda r: r["evenness"]["negative-ratio"])
p2 = col(lambda r: r["evenness"]["P2"])
wall = col(lambda r: r["wall-seconds"])
print(",".join([
    str(len(rows)),
    f"{statistics.median(neg):.3f}", f"{max(neg):.3f}",
    f"{statistics.median(p2):.3f}", f"{max(p2):.3f}",
    str(max(col(lambda r: r["overlap-count"]))), str(max(col(lambda r: r["elements-outside"]))),
    str(max(col(lambda r: r["self-intersecting-outlines"]))),
    f"{statistics.median(col(lambda r: r['iterations'])):.0f}",
    f"{statistics.median(wall):.2f}", f"{max(wall):.2f}",
    f"{statistics.median(col(lambda r: r['primary-area-cv'])):.3f}"]))
PY
)
  echo "$stamp,$commit,$name,\"$extra\",$row" | sed 's/^\([^,]*,[^,]*,[^,]*\),\("[^"]*"\),\([^,]*\)/\1,\3,\2/' | tee -a "$csv"
done

# Contact sheet: seed 1 of every scene side by side, drawn by pak render from one SVG.
python3 - "$work/quality-sheet.svg" "${sheet[@]}" <<'PY'
import re, sys
out, entries = sys.argv[1], sys.argv[2:]
cell, pad, label = 500, 20, 0  # scenes left to right in the order run (a to e)
parts = []
for k, entry in enumerate(entries):
    name, path = entry.split(":", 1)
    text = open(path).read()
    box = [float(v) for v in re.search(r'viewBox="([^"]+)"', text).group(1).split()]
    body = text[text.index(">", text.index("<svg")) + 1:text.rindex("</svg>")]
    body = re.sub(r' id="[^"]*"', "", body)  # ids repeat across packings
    scale = cell / max(box[2], box[3])
    x = pad + k * (cell + pad)
    parts.append(f'<g transform="translate({x},{pad + label}) scale({scale}) translate({-box[0]},{-box[1]})">{body}</g>')
width = pad + len(entries) * (cell + pad)
open(out, "w").write(f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" '
                     f'width="{width}" height="{cell + 2 * pad + label}" viewBox="0 0 {width} {cell + 2 * pad + label}">'
                     + "".join(parts) + "</svg>\n")
PY
"$pak" render "$work/quality-sheet.svg" -o "$work/quality-sheet.png" --width 2400 --background white
echo "bench/quality: contact sheet $work/quality-sheet.png"
