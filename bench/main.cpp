// pak_bench's entry point (Google Benchmark); the benchmarks live in bench/*_bench.cpp.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
