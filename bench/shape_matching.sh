#!/usr/bin/env bash
# Shape matching (thesis 4.7): how close the element art comes to the container's salient
# convex corners, with and without --shape-matching, over 5 seeds on the heart (its tip) and
# a five-pointed star. Prints mean ± sd of the per-run mean corner distance (canonical units:
# the container's bounding square is 1000 wide) and the matching stage's time, and writes the
# per-run rows to bench/shape-matching-results.csv.
# Usage: bench/shape_matching.sh [build-dir]
set -euo pipefail
build=${1:-build/rel}
pak="$build/pak"
data=../shared/data
work=out/shape-matching
mkdir -p "$work"
if [ ! -d "$data/repulsionpak" ]; then echo "shape_matching.sh: needs $data/repulsionpak" >&2; exit 1; fi
declare -A containers=(
  [heart]="$data/repulsionpak/containers/heart.path"
  [star]="$data/mdi/star.svg"
)
csv=bench/shape-matching-results.csv
echo "container,seed,matching,corners,corner_art_distance_mean,matching_ms,iterations,fill_art,overlaps,outside" > "$csv"
for name in heart star; do
  for seed in 1 2 3 4 5; do
    for mode in off on; do
      flag=(); [ "$mode" = on ] && flag=(--shape-matching)
      out="$work/$name-s$seed-$mode"
      "$pak" pack --container "${containers[$name]}" --elements "$data/repulsionpak/animals" --count 27 \
        --seed "$seed" "${flag[@]}" -o "$out.svg" --report "$out.json" --quiet
      python3 - "$out.json" "$name" "$seed" "$mode" >> "$csv" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
ms = r.get("shape-matching", {}).get("matching-seconds", 0.0) * 1000
print(f"{sys.argv[2]},{sys.argv[3]},{sys.argv[4]},{len(r['salient-corners'])},{r['corner-art-distance-mean']:.3f},"
      f"{ms:.2f},{r['iterations']},{r['fill-ratio-art']:.4f},{r['overlap-count']},{r['elements-outside']}")
PY
    done
  done
done
python3 - "$csv" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("container  matching  corners  corner→art distance mean ± sd  matching ms mean  art fill mean  overlaps  outside")
for name in ("heart", "star"):
    for mode in ("off", "on"):
        rs = [r for r in rows if r["container"] == name and r["matching"] == mode]
        d = [float(r["corner_art_distance_mean"]) for r in rs]
        ms = [float(r["matching_ms"]) for r in rs]
        fill = [float(r["fill_art"]) for r in rs]
        print(f"{name:9s}  {mode:8s}  {rs[0]['corners']:7s}  {statistics.mean(d):8.2f} ± {statistics.stdev(d):6.2f}"
              f"               {statistics.mean(ms):8.1f}          {statistics.mean(fill):.3f}       "
              f"{sum(int(r['overlaps']) for r in rs):8d}  {sum(int(r['outside']) for r in rs):7d}")
PY
