#!/usr/bin/env bash
# Installs the Debian packages Pak needs to build, test and benchmark.
# Idempotent: installs only what is missing, and says what it installs.
# --docs adds what only the docs' screenshots need (a virtual X server, a screen grabber and
# a keyboard/mouse driver for it); `make test` never passes it.
set -euo pipefail

packages=(
  build-essential cmake pkg-config time python3
  clang                 # the release build's compiler (Makefile: RELEASE_CXX)
  libpolyclipping-dev   # offsets, booleans (Clipper)
  libgeos-dev           # Delaunay triangulation (GEOS C API)
  libsvgpp-dev libboost-dev  # SVG parsing (SVG++ with rapidxml_ns)
  libeigen3-dev         # sparse linear algebra
  libnanoflann-dev      # k-d tree
  libcairo2-dev         # PNG rendering and plots
  libcgif-dev           # GIF output
  libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  help2man              # man pages from each command's --help (make install)
  libxml2-utils         # xmllint: the tests check that every SVG is well-formed
  inkscape              # the Inkscape extension and its test; inkscape ships inkex, which
  python3-lxml python3-cssselect python3-numpy  # imports these (only recommended by inkscape)
  python3-dev pybind11-dev  # the `pak` Python module (make python), built for Debian's python3
  python3-pytest        # its tests (tests/python, run by make test)
  python3-shapely       # shapely geometries as the module's inputs, and their tests
)

# `make fuzz` (--fuzz): clang's libFuzzer runtime; `make test` replays the fuzz corpus with
# g++ and does not need it.
fuzz_packages=(
  libclang-rt-dev
)

docs_packages=(
  xvfb                  # a headless X server for a real Inkscape window
  imagemagick           # `import` grabs that window as a PNG
  xdotool               # opens menus and dialogues in it
)

for arg in "$@"; do
  case "$arg" in
    --docs) packages+=("${docs_packages[@]}") ;;
    --fuzz) packages+=("${fuzz_packages[@]}") ;;
    *) echo "install-deps: unknown option '$arg' (known: --docs, --fuzz)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: done"
