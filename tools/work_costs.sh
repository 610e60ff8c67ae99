#!/usr/bin/env bash
# The effort control's work constants (docs/maths.md#effort-work): times every counted
# operation with vrlis_bench (the batched gathers, the bounds, a call's loop, on both paths of
# core/dispatch.hpp's lanes; the example renderer's rays, calls and pixels) and writes them,
# in nanoseconds of this machine, into
# include/vrlis/effort/work_costs.hpp and integration/include/vrlis_integration/renderer_work.hpp.
# Images with the effort control on change with them: commit them with what they measured.
#   tools/work_costs.sh [--dry-run]    (~5 minutes; --dry-run prints and writes nothing)
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
build_preset release vrlis_bench
mkdir -p out/work_costs
timed=(--benchmark_repetitions=3 --benchmark_min_time=0.1 --benchmark_format=json)
build/bench/vrlis_bench --benchmark_filter='^(GatherBatch|SurfaceGatherBatch|Work)/' "${timed[@]}" \
  >out/work_costs/bench.json
build/bench/vrlis_bench --vrlis_lanes=built --benchmark_filter='^(GatherBatch/|SurfaceGatherBatch/|Work/(bound|call|mixture))' \
  "${timed[@]}" >out/work_costs/bench_built.json
write=--write
[ "${1:-}" = "--dry-run" ] && write=""
/usr/bin/python3 bench/work_costs.py out/work_costs/bench.json out/work_costs/bench_built.json $write
