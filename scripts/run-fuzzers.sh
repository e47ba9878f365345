#!/usr/bin/env bash
# Runs each libFuzzer target `make fuzz` built, one after another, for a given time.
# Usage: run-fuzzers.sh BUILD_DIR SECONDS TARGET...
# Each target starts from its seed corpus and regressions (tests/fuzz/) and keeps what it
# learns in BUILD_DIR/corpus/TARGET, so a later run goes on from there. A finding (crash,
# sanitizer report, exception other than InputError, an input over the time or memory bound)
# is saved in BUILD_DIR/findings/TARGET/; the script says how to minimise it and where to put
# it, runs the remaining targets, and exits 1.
# FUZZ_MAX_LEN (bytes), FUZZ_RSS_MB and FUZZ_TIMEOUT (seconds per input) override the bounds.
# FUZZ_KEEP_GOING=1 fuzzes on past a finding (libFuzzer's fork mode), to collect several in
# one long run while a known one waits for its fix; each is saved all the same.
set -uo pipefail
cd "$(dirname "$0")/.."

build=$1 seconds=$2
shift 2
max_len=${FUZZ_MAX_LEN:-65536}
rss_mb=${FUZZ_RSS_MB:-2048}
timeout=${FUZZ_TIMEOUT:-10}
keep_going=()
[ "${FUZZ_KEEP_GOING:-0}" = 1 ] && keep_going=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)

dictionary_of() {
  case "$1" in
    svg_reader | packing_reader) echo tests/fuzz/svg.dict ;;
    path_reader) echo tests/fuzz/path.dict ;;
    *) echo tests/fuzz/json.dict ;;
  esac
}

found=0
for target in "$@"; do
  program=$build/tests/fuzz/fuzz_$target
  corpus=$build/corpus/$target findings=$build/findings/$target log=$build/logs/$target.log
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  seeds=(tests/fuzz/corpus/"$target")
  [ -d tests/fuzz/regressions/"$target" ] && seeds+=(tests/fuzz/regressions/"$target")
  echo "fuzz: $target for ${seconds} s (log: $log)"
  started=$build/logs/$target.started
  touch "$started"
  "$program" "$corpus" "${seeds[@]}" -dict="$(dictionary_of "$target")" -max_total_time="$seconds" \
    -max_len="$max_len" -rss_limit_mb="$rss_mb" -timeout="$timeout" -artifact_prefix="$findings/" \
    -print_final_stats=1 "${keep_going[@]}" > "$log" 2>&1
  status=$?
  # libFuzzer's closing lines: runs, coverage, corpus, speed.
  grep -E '^#[0-9]+:?[[:space:]].*(cov|DONE)' "$log" | tail -n 1 | sed 's/^/  /'
  grep -E '^Done [0-9]+ runs|^stat::number_of_executed_units|^stat::average_exec_per_sec|^stat::peak_rss_mb' "$log" | sed 's/^/  /'
  new_findings=$(find "$findings" -type f -newer "$started" ! -name '*.min' | sort)
  if [ "$status" -ne 0 ] || [ -n "$new_findings" ]; then
    found=1
    grep -m 1 -E 'ERROR: |fuzz: finding|SUMMARY: ' "$log" | sed 's/^/  /'
    echo "fuzz: $target: FINDING (exit $status): ${new_findings:-see $log}"
    for artifact in $new_findings; do
      echo "  minimise: $program -minimize_crash=1 -runs=20000 -exact_artifact_path=$artifact.min $artifact"
    done
    echo "  once fixed, keep it: cp FILE.min tests/fuzz/regressions/$target/<what-it-is>"
  fi
done
if [ "$found" -ne 0 ]; then
  echo "fuzz: findings above; make test replays tests/fuzz/regressions/ once they are copied there"
  exit 1
fi
echo "fuzz: no finding in $# targets"
