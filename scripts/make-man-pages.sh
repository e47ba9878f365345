#!/usr/bin/env bash
# Writes a man page per command (pak.1, pak-pack.1, …) into OUT_DIR from each command's
# --help, with help2man. Usage: scripts/make-man-pages.sh PAK_BINARY OUT_DIR VERSION
set -euo pipefail
pak=$1 out=$2 version=$3
mkdir -p "$out"
# Each command's one-line description, for the NAME section.
names=("pack|fill a container with deformable elements (RepulsionPak)"
       "flow|fill containers with elements bent along a flow (FLOWPAK)"
       "animate|pack animated elements into a container and render the animation (AnimationPak)"
       "metrics|measure how even the negative space of packings is"
       "inspect|show what Pak sees in SVG or .path files"
       "render|draw an SVG or .path file as Pak understood it")
common=(--no-info --no-discard-stderr --version-string="$version" --section=1 --source="pak $version")
help2man "${common[@]}" --name="fill containers with deformable elements" --output="$out/pak.1" "$pak"
for entry in "${names[@]}"; do
  command=${entry%%|*}
  # help2man runs "PROGRAM --help" through the shell: the command rides along with the binary.
  help2man "${common[@]}" --name="${entry#*|}" --output="$out/pak-$command.1.tmp" "$pak $command"
  # The title is the page's name (pak-flow), not the program's.
  sed "s/^\.TH PAK /.TH PAK-${command^^} /" "$out/pak-$command.1.tmp" > "$out/pak-$command.1"
  rm "$out/pak-$command.1.tmp"
done
