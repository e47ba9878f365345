#!/usr/bin/env bash
# The release build (clang, Makefile's RELEASE_CXX) and the test build (g++, sanitizers) give
# the same outputs byte for byte: the golden hashes, checked in the test build, then hold for
# the pak users run. One short run of each simulator. Usage: same_results_test.sh TEST_PAK
# RELEASE_PAK SOURCE_DIR
set -euo pipefail
test_pak=$1 release_pak=$2 src=$3
[ -x "$release_pak" ] || { echo "same_results_test: skipped: no release build at $release_pak"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "same_results_test: $*" >&2; exit 1; }
run_both() {  # NAME OUTPUT ARGS...: runs both builds, compares OUTPUT (relative to each run's folder)
  local name=$1 output=$2; shift 2
  for build in test release; do
    local pak=$test_pak
    [ "$build" = release ] && pak=$release_pak
    mkdir -p "$work/$build"
    (cd "$work/$build" && "$pak" "$@" --quiet) || fail "$name: the $build build failed"
  done
  cmp -s "$work/test/$output" "$work/release/$output" || fail "$name: $output differs between the builds"
  echo "same_results_test: $name: $output is the same ($(sha256sum < "$work/test/$output" | cut -c1-12))"
}
run_both pack pack.svg pack --container "$src/examples/scene.svg" --elements "$src/examples/elements" \
  --max-iterations 300 -o pack.svg
run_both flow flow.svg flow "$src/examples/flow/koi.svg" -e "$src/examples/flow/elements" -o flow.svg
run_both animate stars/animation.svg animate -c "$src/examples/animate/stars/disc.svg" \
  -a "$src/examples/animate/stars/stars.json" --slices 12 --max-iterations 150 --frames 6 --no-gif -o stars
