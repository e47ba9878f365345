#!/usr/bin/env bash
# Runs `pak inspect` on every SVG of real icon sets (downloaded from npm into a temporary
# folder, never into the repository: they are not ours to ship) and of Inkscape's own examples
# and templates, and tabulates what Pak made of them. See docs/icon-sets.md.
#
# Usage: scripts/icon-survey.sh [PAK] [SAMPLE] [COMPARE]
#   PAK      the pak binary (default: build/release/pak)
#   SAMPLE   at most this many files per set, every k-th of the sorted list (default: 0, all)
#   COMPARE  also draw this many files per set with `pak render` and with Inkscape and count
#            the pixels that differ (default: 0, none; needs inkscape and ImageMagick's compare)
# Environment: ICON_SURVEY_DIR reuses (or keeps) downloads there instead of a fresh temporary
# folder that is deleted at the end; the per-file results (results.tsv) are written there too.
# ICON_SURVEY_SETS="openmoji flag-icons" surveys only those sets.
# The report (Markdown, a section per set) goes to stdout; progress to stderr.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
pak=$(realpath "${1:-$here/../build/release/pak}")
sample=${2:-0}
compare=${3:-0}
wanted() { [[ -z ${ICON_SURVEY_SETS:-} || " $ICON_SURVEY_SETS " == *" $1 "* ]]; }
[[ -x $pak ]] || { echo "icon-survey: no pak binary at $pak (build it first)" >&2; exit 2; }

if [[ -n ${ICON_SURVEY_DIR:-} ]]; then
  work=$ICON_SURVEY_DIR
  mkdir -p "$work"
else
  work=$(mktemp -d /tmp/pak-icon-survey.XXXXXX)
  trap 'rm -rf "$work"' EXIT
fi

# set name | npm tarball (versions pinned, so a re-run surveys the same files) | SVG folder in it
sets=(
  "mdi|https://registry.npmjs.org/@mdi/svg/-/svg-7.4.47.tgz|package/svg"
  "simple-icons|https://registry.npmjs.org/simple-icons/-/simple-icons-16.37.0.tgz|package/icons"
  "tabler-outline|https://registry.npmjs.org/@tabler/icons/-/icons-3.52.0.tgz|package/icons/outline"
  "tabler-filled|https://registry.npmjs.org/@tabler/icons/-/icons-3.52.0.tgz|package/icons/filled"
  "bootstrap-icons|https://registry.npmjs.org/bootstrap-icons/-/bootstrap-icons-1.13.2.tgz|package/icons"
  "twemoji|https://registry.npmjs.org/twemoji-svg/-/twemoji-svg-17.0.2.tgz|package/dist"
  "openmoji|https://registry.npmjs.org/openmoji/-/openmoji-17.0.0.tgz|package/color/svg"
  "flag-icons|https://registry.npmjs.org/flag-icons/-/flag-icons-7.5.0.tgz|package/flags"
)

lists=()
for entry in "${sets[@]}"; do
  IFS='|' read -r name url folder <<< "$entry"
  wanted "$name" || continue
  unpacked=$work/$(basename "$url" .tgz)
  if [[ ! -d $unpacked ]]; then
    echo "icon-survey: fetching $url" >&2
    curl -sSfL "$url" -o "$unpacked.tgz"
    mkdir -p "$unpacked"
    tar -xzf "$unpacked.tgz" -C "$unpacked"
  fi
  find "$unpacked/$folder" -name '*.svg' | LC_ALL=C sort > "$work/$name.files"
  lists+=("$name=$work/$name.files")
done
# Inkscape's examples and templates, when Inkscape is installed (.svgz is compressed: not read).
for name in examples templates; do
  folder=/usr/share/inkscape/$name
  [[ -d $folder ]] && wanted "inkscape-$name" || continue
  find "$folder" -maxdepth 1 -name '*.svg' | LC_ALL=C sort > "$work/inkscape-$name.files"
  lists+=("inkscape-$name=$work/inkscape-$name.files")
done

python3 "$here/icon_survey.py" --pak "$pak" --sample "$sample" --compare "$compare" --results "$work/results.tsv" \
  "${lists[@]}"
