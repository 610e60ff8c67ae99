#!/usr/bin/env bash
# How far counted work (docs/maths.md#effort-work) sits from measured time: vrl_render with its
# defaults on every scene, one thread, and the passes' counted work, light and camera (in
# nanoseconds of the machine tools/work_costs.sh measured), over their measured seconds. A ratio of 1 is a model exact in scale; what the price needs is the same ratio
# across a scene's operations, so the spread between scenes is the figure to read.
#   tools/work_check.sh [vrl_render arguments, e.g. --effort off]
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
build_preset release vrl_render
mkdir -p out/work_check
echo "| scene | counted work (s) | measured (s) | counted / measured |"
echo "|---|---|---|---|"
for scene in bidirectional room cube corner cloud fog; do
  build/examples/vrl_render --scene "$scene" --width 64 --height 64 --spp 8 --threads 1 --quiet --json \
    --out "out/work_check/$scene" "$@" >"out/work_check/$scene.json"
  /usr/bin/python3 - "out/work_check/$scene.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
w, t = j["counted_work"] * 1e-9, j["render_time_s"]
print(f"| {j['scene']} | {w:.3f} | {t:.3f} | {w / t:.2f} |")
PY
done
