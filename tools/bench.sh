#!/usr/bin/env bash
# Speed and accuracy of the camera samplers: builds Release, runs vrlis_bench (Google
# Benchmark, repetitions, medians, JSON) and vrlis_accuracy (quadrature, JSON), then draws
# the charts and the table:
#   <outdir>/bench.json, accuracy.json, accuracy.txt, table.md,
#   speed_accuracy.{png,svg}, efficiency.{png,svg}
# and copies the charts to docs/figures/ and the table to docs/bench.md (unless
# VRLIS_BENCH_NO_DOCS=1).
#
#   tools/bench.sh [outdir=out/bench]
# Environment: VRLIS_BENCH_BUILD (a configured build dir; default: the `release` preset's,
# build/), VRLIS_BENCH_REPS (5),
# VRLIS_BENCH_MIN_TIME (0.1 s per repetition), VRLIS_ACCURACY_PAIRS (256), VRLIS_BENCH_PIN (a CPU
# number: vrlis_bench runs pinned to it with taskset, for a shared machine whose cores are
# unequally loaded).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/bench}
build=${VRLIS_BENCH_BUILD:-build}
reps=${VRLIS_BENCH_REPS:-5}
min_time=${VRLIS_BENCH_MIN_TIME:-0.1}
pairs=${VRLIS_ACCURACY_PAIRS:-256}

if [ -z "${VRLIS_BENCH_BUILD:-}" ]; then  # (the CMake `bench` target passes its own, configured build)
  source tools/lib.sh
  tools/deps.sh charts
  build_preset release vrlis_bench vrlis_accuracy vrlis_samplers  # vrlis_samplers: the sampler list (tools/samplers.py)
fi
mkdir -p "$out"

echo "== vrlis_bench ($reps repetitions, interleaved; medians)"
pin=()
[ -z "${VRLIS_BENCH_PIN:-}" ] || pin=(taskset -c "$VRLIS_BENCH_PIN")
"${pin[@]}" "$build/bench/vrlis_bench" --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
  --benchmark_enable_random_interleaving=true --benchmark_min_time="$min_time" \
  --benchmark_out="$out/bench.json" --benchmark_out_format=json

echo "== vrlis_accuracy ($pairs pairs per g)"
"$build/bench/vrlis_accuracy" --pairs "$pairs" --json "$out/accuracy.json" | tee "$out/accuracy.txt"

model=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
machine="${model:-unknown CPU}, $(nproc) cores (lscpu: $(lscpu | sed -n 's/^CPU(s): *//p' | head -1) CPUs), $(uname -sr)"
command="tools/bench.sh${1:+ $1}"
/usr/bin/python3 bench/plot.py --bench "$out/bench.json" --accuracy "$out/accuracy.json" --out "$out" \
  --machine "$machine" --command "$command" --date "$(date -u '+%Y-%m-%d %H:%M UTC')" >/dev/null

if [ "${VRLIS_BENCH_NO_DOCS:-0}" != 1 ]; then
  mkdir -p docs/figures
  cp "$out"/speed_accuracy.png "$out"/speed_accuracy.svg "$out"/efficiency.png "$out"/efficiency.svg docs/figures/
  # keep the section tools/speed.sh generates
  { cat "$out/table.md"; [ ! -f docs/bench.md ] || sed -n '/^<!-- speed -->$/,$p' docs/bench.md; } >"$out/bench.md.new"
  mv "$out/bench.md.new" docs/bench.md
fi
echo "== wrote $out/table.md and the charts$([ "${VRLIS_BENCH_NO_DOCS:-0}" != 1 ] && echo '; updated docs/bench.md and docs/figures/')"
