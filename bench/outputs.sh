#!/usr/bin/env bash
# The SVG of every bench scene, run once, and their SHA-256 sums: what a refactoring must not
# change. Run it on two builds and compare the lists:
#   bench/outputs.sh build/release out/outputs-before > before.txt
#   bench/outputs.sh build/release out/outputs-after > after.txt && diff before.txt after.txt
# Each line is "sha256  scene/file". Animation scenes hash their keyframe SVG and every SVG
# frame; a seed reproduces a run bit for bit, whatever the thread count.
# Usage: bench/outputs.sh [build-dir] [output-dir]
set -euo pipefail
build=${1:-build/release}
out=${2:-out/outputs}
pak="$build/pak"
data=../shared/data
[ -d "$data" ] || data=/work/shared/data
mkdir -p "$out"

pack() {  # NAME ARGS...
  local name=$1; shift
  "$pak" pack "$@" -o "$out/$name.svg" --quiet
}
pack example --container examples/scene.svg --elements examples/elements
pack example-tile --tile 1000,1000 --elements examples/elements --count 20 --seed 7
pack regions -c examples/regions.svg -e examples/elements
pack rooms -c examples/rooms.svg -e examples/elements/cat.svg examples/elements/mushroom.svg --count 24
pack leaves -c examples/scene.svg -e examples/elements/leaf.svg --count 14
pack nested -c "$out/leaves.svg" --container-layer elements -e examples/elements/star.svg examples/elements/flower.svg \
  --count 56 --gap 6
pack orientation-field -c examples/band.svg -e examples/elements/bird.svg --count 24 --orientation-field x:0:180
pack orientation-upright -c examples/band.svg -e examples/elements/bird.svg --count 24 --orientation upright
pack fixed -c examples/fixed-scene.svg -e examples/elements --count 20
pack rigid -c examples/scene.svg -e examples/elements --preset rigid --max-iterations 1500
if [ -d "$data/repulsionpak" ]; then
  heart=$data/repulsionpak/containers/heart.path
  animals=$data/repulsionpak/animals
  pack animals-heart --container "$heart" --elements "$animals" --count 27
  pack animals-heart-secondary --container "$heart" --elements "$animals" --count 27 --secondary "$data/repulsionpak/small_cat"
  pack animals-tile --tile 1000,1000 --elements "$animals" --count 27 --seed 2
  pack heart-matching --container "$heart" --elements "$animals" --count 27 --seed 3 --shape-matching
  pack star-matching --container "$data/mdi/star.svg" --elements "$animals" --count 27 --seed 2 --shape-matching
  pack mdi-heart --container "$data/mdi/heart.svg" --elements "$data"/mdi/{cat,dog,rabbit,bird,fish,penguin,turtle,snail}.svg
else
  echo "bench/outputs.sh: $data not found; bundled scenes only" >&2
fi

flow() {  # NAME ARGS...
  local name=$1; shift
  "$pak" flow "$@" -e examples/flow/elements -o "$out/flow-$name.svg" --quiet
}
flow koi examples/flow/koi.svg
flow medallion examples/flow/medallion.svg
flow koi-50 examples/flow/koi.svg --gap 30 --min-length 45 --max-length 180

animate() {  # NAME CONTAINER ANIMATION ARGS...
  local name=$1 container=$2 animation=$3; shift 3
  rm -rf "$out/animate-$name"
  "$pak" animate -c "$container" -a "$animation" -o "$out/animate-$name" --frames 20 --svg-frames --no-gif --quiet "$@"
}
animate stars examples/animate/stars/disc.svg examples/animate/stars/stars.json --slices 40
animate chase examples/animate/chase/annulus.svg examples/animate/chase/chase.json --slices 40

cd "$out"
find . -name '*.svg' | sed 's|^\./||' | LC_ALL=C sort | xargs sha256sum
