#!/usr/bin/env bash
# Ctrl-C (SIGINT) on a long run: the first stops pack, flow and animate as --time-limit would,
# and they write a clean result with stop-reason "interrupted"; a second aborts (exit 130)
# and leaves no output and no temporary file. Usage: interrupt_test.sh PAK SOURCE_DIR
set -euo pipefail
pak=$1 source=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "interrupt_test: $*" >&2; exit 1; }
cd "$source"

# Starts pak in the background with stderr to $out/NAME.log; waits (at most 300 s) until the
# log shows PATTERN, the sign that the simulation runs.
start() {  # NAME PATTERN ARGS...
  local name=$1 pattern=$2
  shift 2
  "$pak" "$@" 2> "$out/$name.log" &
  pid=$!
  for _ in $(seq 3000); do
    grep -q "$pattern" "$out/$name.log" && return 0
    kill -0 "$pid" 2> /dev/null || fail "$name ended before it was interrupted: $(tail -3 "$out/$name.log")"
    sleep 0.1
  done
  kill -9 "$pid"
  fail "$name never showed '$pattern'"
}
# Waits for $pid (at most 300 s, then fails): its exit code in $rc.
finish() {  # NAME
  for _ in $(seq 3000); do
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
  done
  kill -0 "$pid" 2> /dev/null && { kill -9 "$pid"; fail "$1 did not stop within 300 s of Ctrl-C"; }
  rc=0
  wait "$pid" || rc=$?
}
field() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"; }
expect_clean_interrupted() {  # NAME REPORT
  [ "$rc" = 0 ] || fail "$1 exited $rc after one Ctrl-C: $(tail -3 "$out/$1.log")"
  [ "$(field "$2" stop-reason)" = interrupted ] || fail "$1: stop-reason $(field "$2" stop-reason)"
}

start flow "refinement 1/" flow examples/flow/koi.svg -e examples/flow/elements --count 40 --iterations 10000 \
  -o "$out/flow.svg" --report "$out/flow.json"
kill -INT "$pid"
finish flow
expect_clean_interrupted flow "$out/flow.json"
[ "$(field "$out/flow.json" overlap-count)" = 0 ] || fail "flow: overlaps after Ctrl-C"
[ "$(field "$out/flow.json" self-intersecting-outlines)" = 0 ] || fail "flow: folded elements after Ctrl-C"
[ -s "$out/flow.svg" ] || fail "flow: no output after Ctrl-C"

start pack "iteration" pack -c examples/scene.svg -e examples/elements --max-iterations 1000000 --stall-epsilon 0 \
  --progress-every 20 -o "$out/pack.svg" --report "$out/pack.json"
kill -INT "$pid"
finish pack
expect_clean_interrupted pack "$out/pack.json"
[ "$(field "$out/pack.json" overlap-count)" = 0 ] || fail "pack: overlaps after Ctrl-C"
[ "$(field "$out/pack.json" elements-outside)" = 0 ] || fail "pack: elements outside after Ctrl-C"

start animate "iteration" animate -c examples/animate/stars/disc.svg -a examples/animate/stars/stars.json --slices 6 \
  --frames 4 --width 80 --max-iterations 1000000 --stall-growth 0 --closeness 1e-9 -o "$out/animate" \
  --report "$out/animate.json"
kill -INT "$pid"
finish animate
expect_clean_interrupted animate "$out/animate.json"
[ "$(field "$out/animate.json" frames-with-overlaps)" = 0 ] || fail "animate: frames overlap after Ctrl-C"
[ -s "$out/animate/animation.gif" ] || fail "animate: no GIF after Ctrl-C"

# Twice: aborted, nothing written.
mkdir "$out/twice"
start twice "iteration" pack -c examples/scene.svg -e examples/elements --max-iterations 1000000 --stall-epsilon 0 \
  --progress-every 20 -o "$out/twice/pack.svg" --png "$out/twice/pack.png" --report "$out/twice/pack.json"
kill -INT "$pid"
sleep 0.05
kill -INT "$pid"
finish twice
[ "$rc" = 130 ] || fail "two Ctrl-C: exit $rc, not 130"
left=$(ls -A "$out/twice")
[ -z "$left" ] || fail "two Ctrl-C left files: $left"
# The animation's output folder, created by the run, goes too while it is empty.
start twice-animate "iteration" animate -c examples/animate/stars/disc.svg -a examples/animate/stars/stars.json \
  --slices 6 --frames 4 --width 80 --max-iterations 1000000 --stall-growth 0 --closeness 1e-9 -o "$out/twice/animate"
kill -INT "$pid"
sleep 0.05
kill -INT "$pid"
finish twice-animate
[ "$rc" = 130 ] || fail "two Ctrl-C on animate: exit $rc, not 130"
left=$(ls -A "$out/twice")
[ -z "$left" ] || fail "two Ctrl-C on animate left: $left"
echo "interrupt_test: flow, pack and animate stop cleanly on Ctrl-C; a second aborts and leaves nothing"
