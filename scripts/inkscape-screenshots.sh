#!/usr/bin/env bash
# Takes the screenshots of docs/inkscape.md from a real Inkscape on a virtual screen (Xvfb):
# the Pack and Flow dialogues over examples/inkscape/demo.svg, each result on the canvas, and
# the Extensions menu.
# Needs `scripts/install-deps.sh --docs` (xvfb, imagemagick, xdotool) and a built pak
# (PAK, else build/release/pak). The extension runs from a throw-away Inkscape profile, so
# the user's own Inkscape settings are neither used nor changed.
# Usage: scripts/inkscape-screenshots.sh [OUTPUT_DIR]   (default docs/images)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images}
pak=${PAK:-$PWD/build/release/pak}
for tool in Xvfb import display xdotool inkscape; do
  command -v "$tool" > /dev/null || { echo "inkscape-screenshots: $tool is missing: scripts/install-deps.sh --docs" >&2; exit 2; }
done
[ -x "$pak" ] || { echo "inkscape-screenshots: no pak at $pak: make release, or set PAK" >&2; exit 2; }

work=$(mktemp -d)
xvfb="" inkscape=""
cleanup() {
  [ -n "$inkscape" ] && kill "$inkscape" 2> /dev/null || true
  [ -n "$xvfb" ] && kill "$xvfb" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

export INKSCAPE_PROFILE_DIR=$work/profile
mkdir -p "$INKSCAPE_PROFILE_DIR/extensions/pak" "$work/bin"
cp inkscape/*.inx inkscape/*.py "$INKSCAPE_PROFILE_DIR/extensions/pak/"
ln -s "$pak" "$work/bin/pak"
export PATH=$work/bin:$PATH

# A screen wide enough for the window and the dialogue side by side; -displayfd picks a free
# display number.
width=1720 height=900
exec 3> "$work/display"
Xvfb -displayfd 3 -screen 0 ${width}x${height}x24 -nolisten tcp 2> "$work/xvfb.log" &
xvfb=$!
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
export DISPLAY=:$(cat "$work/display")
convert -size ${width}x${height} xc:'#d9d9d9' "$work/background.png"

window() {  # NAME-REGEX: waits (at most 60 s) for a window so named; prints its id
  for _ in $(seq 120); do
    xdotool search --name "$1" 2> /dev/null | head -n 1 && return 0
    sleep 0.5
  done
  echo "inkscape-screenshots: no window '$1' appeared" >&2
  exit 1
}
click() { xdotool mousemove "$1" "$2" click --repeat "${3:-1}" 1; sleep 0.5; }  # X Y [COUNT]
shot() {  # FILE
  xdotool mousemove $((width - 10)) $((height - 10))
  sleep 1
  import -window root "$work/shot.png"
  convert "$work/shot.png" -strip "$1"
}
wait_modified() {  # DOCUMENT-NAME: until Inkscape marks the document changed (at most 5 minutes)
  # Inkscape is busy while the extension runs, and takes no clicks until it is done; its title
  # then starts with `*`.
  for _ in $(seq 300); do
    xdotool search --name "^\*$1 - Inkscape" > /dev/null 2>&1 && { sleep 2; return 0; }
    sleep 1
  done
  echo "inkscape-screenshots: the extension did not change the document within 5 minutes" >&2
  exit 1
}

# One session per dialogue: DOCUMENT, SELECTED-IDS, EXTENSION, DIALOGUE-TITLE, NAME,
# then the field to fill (X Y relative to the dialogue) and its text, then Apply and Close.
session() {
  local document=$1 ids=$2 action=$3 title=$4 name=$5 field_x=$6 field_y=$7 text=$8
  local apply_x=$9 apply_y=${10} close_x=${11} close_y=${12} main dialog dialog_x=1126 dialog_y=130
  inkscape --with-gui "$document" --actions="select-by-id:$ids;$action" > "$work/inkscape.log" 2>&1 &
  inkscape=$!
  main=$(window "$(basename "$document") - Inkscape")
  dialog=$(window "^$title\$")
  sleep 3
  # No window manager: place the windows by hand.
  xdotool windowsize "$main" $((dialog_x - 6)) "$height" windowmove "$main" 0 0
  xdotool windowmove "$dialog" "$dialog_x" "$dialog_y"
  sleep 1
  # Grey, not black, where the windows are not (it exits 1 even when it works); set after the
  # windows moved, which leaves the uncovered screen unpainted without a window manager.
  display -window root "$work/background.png" || true
  xdotool windowfocus --sync "$main" key --window "$main" 5  # zoom to the page
  sleep 1
  xdotool windowfocus --sync "$dialog"
  click $((dialog_x + field_x)) $((dialog_y + field_y)) 3
  xdotool key ctrl+a type --delay 60 "$text"
  xdotool key Tab
  shot "$out/inkscape-$name-dialog.png"
  click $((dialog_x + apply_x)) $((dialog_y + apply_y))
  wait_modified "$(basename "$document")"
  click $((dialog_x + close_x)) $((dialog_y + close_y))
  xdotool windowsize "$main" "$width" "$height"
  sleep 1
  xdotool windowfocus --sync "$main" key --window "$main" Escape
  [ "$name" = pack ] && xdotool key --window "$main" ctrl+shift+l  # the Layers panel
  sleep 2
  xdotool key --window "$main" 5
  sleep 2
  shot "$out/inkscape-$name-result.png"
  kill "$inkscape"
  wait "$inkscape" 2> /dev/null || true
  inkscape=""
}

cp examples/inkscape/demo.svg "$work/demo.svg"
session "$work/demo.svg" heart,star,leaf,ladybird,drop,flower org.pak.pack Pack pack \
  419 190 1.5mm 506 460 417 460
# The flow picture shows the guides, which demo.svg keeps hidden.
sed 's/id="guides" style="display:none"/id="guides" style="display:inline"/' examples/inkscape/demo.svg > "$work/flow-demo.svg"
session "$work/flow-demo.svg" heart,leaf org.pak.flow Flow flow 511 152 60 544 487 457 487
# The menu: Extensions, then Pak (its place in the alphabetical list of Inkscape's own).
inkscape --with-gui "$work/demo.svg" > "$work/inkscape.log" 2>&1 &
inkscape=$!
main=$(window "demo.svg - Inkscape")
sleep 3
xdotool windowsize "$main" "$width" "$height" windowmove "$main" 0 0
sleep 1
click 423 12
xdotool mousemove 430 313
sleep 2
import -window root "$work/shot.png"
convert "$work/shot.png" -crop 760x360+360+0 +repage -strip "$out/inkscape-menu.png"
ls -l "$out"/inkscape-*.png
