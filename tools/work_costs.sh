#!/usr/bin/env bash
# The effort control's work constants (docs/maths.md#effort-work): times every counted
# operation with vrlis_bench (the batched gathers, the bounds, a call's loop; the example
# renderer's rays, calls and pixels) and writes them, in nanoseconds of this machine, into
# include/vrlis/effort/work_costs.hpp and integration/include/vrlis_integration/renderer_work.hpp.
# Images with the effort control on change with them: commit them with what they measured.
#   tools/work_costs.sh [--dry-run]    (~3 minutes; --dry-run prints and writes nothing)
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
build_preset release vrlis_bench
mkdir -p out/work_costs
build/bench/vrlis_bench --benchmark_filter='^(GatherBatch|SurfaceGatherBatch|Work)/' --benchmark_repetitions=3 \
  --benchmark_min_time=0.1 --benchmark_format=json >out/work_costs/bench.json
write=--write
[ "${1:-}" = "--dry-run" ] && write=""
/usr/bin/python3 bench/work_costs.py out/work_costs/bench.json $write
