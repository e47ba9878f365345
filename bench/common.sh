# Shared by the bench scripts (source it): the build folder, run count, paths, the commit and
# time stamp of the rows, and small helpers.
#   build  pak binary folder (first argument, default build/release)
#   runs   BENCH_RUNS (default 3): runs per scene, the rows give medians
#   data   ../shared/data (or /work/shared/data), which may be absent in a user's clone
build=${1:-build/release}
runs=${BENCH_RUNS:-3}
pak="$build/pak"
data=../shared/data
[ -d "$data" ] || data=/work/shared/data
work=out/bench
mkdir -p "$work"
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
stamp=$(date -u +%Y-%m-%dT%H:%M:%SZ)

# bench_csv FILE HEADER: creates FILE with HEADER unless it exists, and prints HEADER.
bench_csv() {
  [ -f "$1" ] || echo "$2" > "$1"
  echo "$2"
}

# json_field FILE KEY: one top-level value of a JSON report.
json_field() {
  python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"
}

# median VALUE...: the median, with three decimals.
median() {
  python3 -c 'import statistics,sys; print(f"{statistics.median(float(v) for v in sys.argv[1:]):.3f}")' "$@"
}
