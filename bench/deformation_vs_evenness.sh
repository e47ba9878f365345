#!/usr/bin/env bash
# Reproduces the thesis's Figure 6.7 finding: more deformation (lower k_edg) gives more even
# negative space. Packs the same library and container with 5 seeds for each k_edg in
# {5, 250, 1000}, calibrates all 15 packings to one negative-space ratio, and reports the
# mean ± sd of Q(d_gap/2) and O(d_gap/2) per k_edg, with the combined plot in docs/images.
# Usage: bench/deformation_vs_evenness.sh [build-dir]   (uses the shared animals if present)
set -euo pipefail
build=${1:-build/release}
pak="$build/pak"
work=out/deformation
mkdir -p "$work" docs/images
if [ -d ../shared/data/repulsionpak ]; then
  scene=(--container ../shared/data/repulsionpak/containers/heart.path --elements ../shared/data/repulsionpak/animals --count 25)
else
  scene=(--container examples/scene.svg --elements examples/elements)
fi
files=()
for k in 5 250 1000; do
  for seed in 1 2 3 4 5; do
    "$pak" pack "${scene[@]}" --k-edge "$k" --seed "$seed" -o "$work/k$k-s$seed.svg" --report "$work/k$k-s$seed.json" --quiet
    files+=("$work/k$k-s$seed.svg")
  done
done
# All packings share the gap option, so one report gives d_gap in the file's units.
"$pak" metrics "${files[@]}" --calibrate --report "$work/k5-s1.json" --json "$work/metrics.json" \
  --plot docs/images/deformation-vs-evenness.png > "$work/table.txt"
python3 - "$work/metrics.json" <<'PY'
import json, re, statistics, sys
packings = json.load(open(sys.argv[1]))["packings"]
by_k = {}
for p in packings:
    k = int(re.search(r"k(\d+)-s\d+\.svg", p["file"]).group(1))
    by_k.setdefault(k, []).append(p)
print("k_edg  packings  negative ratio  Q(d_gap/2) mean ± sd   O(d_gap/2) mean ± sd   largest empty r")
for k in sorted(by_k):
    ps = by_k[k]
    q = [p["Q-half-gap"] for p in ps]
    o = [p["O-half-gap"] for p in ps]
    r = [p["largest-empty-radius"] for p in ps]
    print(f"{k:5d}  {len(ps):8d}  {ps[0]['negative-ratio']:14.4f}  {statistics.mean(q):.5f} ± {statistics.stdev(q):.5f}   "
          f"{statistics.mean(o):.5f} ± {statistics.stdev(o):.5f}   {statistics.mean(r):.3f}")
PY
