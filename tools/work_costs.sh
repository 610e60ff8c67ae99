#!/usr/bin/env bash
# The effort control's work constants (docs/maths.md#effort-work): times every counted
# operation with vrlis_bench (the batched gathers, the bounds, a call's loop, on both paths of
# core/dispatch.hpp's lanes; the example renderer's rays, calls and pixels) and writes them,
# in nanoseconds of this machine, into
# include/vrlis/effort/work_costs.hpp and integration/include/vrlis_integration/renderer_work.hpp.
# Images with the effort control on change with them: commit them with what they measured.
#   tools/work_costs.sh [--dry-run]    (~6 minutes; --dry-run prints and writes nothing)
# The renderer's constants are residuals: a call's or a pixel's time less the work it counts at
# the constants the build holds. So a written run measures twice, the second time on a build
# of the first's constants; run it on a quiet machine (medians of five repetitions).
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
mkdir -p out/work_costs
measure() {
  build_preset release vrlis_bench
  local timed=(--benchmark_repetitions=5 --benchmark_min_time=0.1 --benchmark_format=json)
  build/bench/vrlis_bench --benchmark_filter='^(GatherBatch|SurfaceGatherBatch|Work)/' "${timed[@]}" \
    >out/work_costs/bench.json
  build/bench/vrlis_bench --vrlis_lanes=built \
    --benchmark_filter='^(GatherBatch/|SurfaceGatherBatch/|Work/(bound|call|mixture))' "${timed[@]}" \
    >out/work_costs/bench_built.json
  /usr/bin/python3 bench/work_costs.py out/work_costs/bench.json out/work_costs/bench_built.json "$@"
}
if [ "${1:-}" = "--dry-run" ]; then
  measure
else
  echo "== round 1 of 2"
  measure --write
  echo "== round 2 of 2 (residuals counted at round 1's constants)"
  measure --write
fi
