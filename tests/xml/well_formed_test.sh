#!/usr/bin/env bash
# Every SVG in examples/ and every kind of SVG pak writes is well-formed XML (xmllint) with
# unique ids: what browsers and Inkscape need to open them. Usage: well_formed_test.sh PAK SOURCE_DIR
set -euo pipefail
pak=$1 source=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "well_formed_test: $*" >&2; exit 1; }
cd "$source"
checked=0
check() {  # FILE: well-formed, and no id given twice
  xmllint --noout "$1" || fail "$1 is not well-formed XML"
  local twice
  twice=$(grep -o ' id="[^"]*"' "$1" | sort | uniq -d | head -3 | tr '\n' ' ')
  [ -z "$twice" ] || fail "$1 repeats ids: $twice"
  checked=$((checked + 1))
}
while IFS= read -r file; do
  xmllint --noout "$file" || fail "$file is not well-formed XML"
  checked=$((checked + 1))
done < <(find examples -name '*.svg' | sort)
# One run of each writer, small.
"$pak" pack -c examples/scene.svg -e examples/elements --count 6 --gap 20 --max-iterations 100 -q -o "$out/pack.svg" --debug-layers
"$pak" pack -c examples/scene.svg -e examples/elements --count 6 --gap 20 --max-iterations 100 -q -o "$out/pack-polyline.svg" --polyline
"$pak" flow examples/flow/koi.svg -e examples/flow/elements --count 20 --iterations 1 -q -o "$out/flow.svg" --debug-layers
"$pak" flow examples/flow/owl.svg -e examples/flow/elements --count 20 --iterations 1 --mirror x=300 -q -o "$out/owl.svg"
"$pak" animate -c examples/animate/stars/disc-moon.svg -a examples/animate/stars/stars.json --slices 6 --frames 2 \
  --width 60 --sheet-frames 2 --svg-keyframes 2 --max-iterations 50 --svg-frames --no-gif -q -o "$out/animate"
"$pak" render examples/flow/owl.svg -o "$out/render.svg"
# A scene with a page in millimetres and layers of its own (copied as written, with what they
# reference), packed with a dashed element, by each command.
"$pak" pack -c tests/svg/poster-scene.svg -e tests/svg/dashed-badge.svg examples/elements/leaf.svg --count 6 \
  --max-iterations 50 -q -o "$out/poster.svg"
"$pak" flow tests/svg/poster-scene.svg -e examples/flow/elements --count 8 --iterations 0 -q -o "$out/poster-flow.svg"
"$pak" animate -c tests/svg/poster-scene.svg -a examples/animate/stars/stars.json --slices 6 --frames 2 \
  --width 60 --sheet-frames 2 --svg-keyframes 2 --max-iterations 50 --svg-frames --no-gif -q -o "$out/poster-animate"
grep -q 'width="210mm" height="210mm" viewBox="0 0 210 210"' "$out/poster.svg" || fail "poster.svg lost the page size"
grep -q 'inkscape:label="Background"' "$out/poster.svg" || fail "poster.svg lost the background layer"
grep -q 'stroke-dasharray=' "$out/poster.svg" || fail "poster.svg lost the dashes"
"$pak" metrics "$out/pack.svg" --plot "$out/plot.svg" > /dev/null
for file in "$out"/*.svg "$out"/animate/*.svg "$out"/animate/svg-frames/*.svg "$out"/poster-animate/*.svg \
  "$out"/poster-animate/svg-frames/*.svg; do check "$file"; done
echo "well_formed_test: $checked SVG files well-formed, the outputs with unique ids"
