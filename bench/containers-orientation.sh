#!/usr/bin/env bash
# Scenes of docs/containers-orientation.md: several containers with holes and their own
# libraries, a packing inside a previous packing's elements, and an orientation field.
# One line per scene: iterations, art fill, overlaps, elements outside, elements per
# container and simulation seconds (a seed reproduces a run, so all but the time are exact).
set -euo pipefail
build=${1:-build/release}
pak="$build/pak"
work=out/bench/containers-orientation
mkdir -p "$work"
summary() {
  python3 - "$1" "$2" <<'PY'
import json, sys
r = json.load(open(sys.argv[2]))
print(f"{sys.argv[1]}: {r['iterations']} iterations ({r['stop-reason']}), art fill {r['fill-ratio-art']:.3f}, "
      f"{r['overlap-count']} overlaps, {r['elements-outside']} outside, per container {r['elements-per-container']}, "
      f"{r['simulation-seconds']:.2f} s")
PY
}
run() {
  local name=$1; shift
  "$pak" pack "$@" -o "$work/$name.svg" --report "$work/$name.json" --quiet
  summary "$name" "$work/$name.json"
}
run regions -c examples/regions.svg -e examples/elements
run rooms -c examples/rooms.svg -e examples/elements/cat.svg examples/elements/mushroom.svg --count 24
run leaves -c examples/scene.svg -e examples/elements/leaf.svg --count 14
run nested -c "$work/leaves.svg" --container-layer elements -e examples/elements/star.svg examples/elements/flower.svg \
  --count 56 --gap 6
run orientation-field -c examples/band.svg -e examples/elements/bird.svg --count 24 --orientation-field x:0:180
run orientation-upright -c examples/band.svg -e examples/elements/bird.svg --count 24 --orientation upright
run orientation-random -c examples/band.svg -e examples/elements/bird.svg --count 24
