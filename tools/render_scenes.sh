#!/usr/bin/env bash
# Renders the comparison scenes into docs/scenes/ (PNG previews and JSON summaries
# committed; EXRs kept out of git) and measures VRL gathers per second with 1 and 2
# threads. Usage: tools/render_scenes.sh [seconds per scene, default 30] [size, default 256]
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_SCENE=${1:-30}
SIZE=${2:-256}
source tools/lib.sh
build_preset release vrl_render >/dev/null
BIN=build/examples/vrl_render
OUT=docs/scenes
mkdir -p "$OUT"
common=(--width "$SIZE" --height "$SIZE" --time "$SECONDS_PER_SCENE" --vrls 64 --seed 1 --sampler cauchy-sum --quiet)
for scene in bidirectional room cube corner cloud fog; do
  "$BIN" --scene "$scene" "${common[@]}" --out "$OUT/$scene.exr" >/dev/null
done
for gather in m2m m2s; do
  "$BIN" --scene corner --gather "$gather" "${common[@]}" --out "$OUT/corner-$gather.exr" >/dev/null
done
rm -f "$OUT"/*.exr

# Throughput: the bidirectional scene is the medium-to-medium gather alone.
for threads in 1 2; do
  "$BIN" --scene bidirectional --width 128 --height 128 --spp 8 --vrls 64 --threads "$threads" --quiet \
    --out "/tmp/vrl_throughput_$threads.exr" >/dev/null
done
/usr/bin/python3 - "$OUT" <<'PY'
import json, sys
out = sys.argv[1]
print("| scene | passes | VRLs | VRL gathers | wall time (s) | gathers/s |")
print("| --- | --- | --- | --- | --- | --- |")
for s in ["bidirectional", "room", "cube", "corner", "corner-m2m", "corner-m2s", "cloud", "fog"]:
    d = json.load(open(f"{out}/{s}.json"))
    print(f"| {s} | {d['passes']} | {d['vrl_count']} | {d['gathers']} | {d['wall_time_s']:.1f} | {d['gathers_per_second']:.3g} |")
t = [json.load(open(f"/tmp/vrl_throughput_{n}.json")) for n in (1, 2)]
print()
print(f"Throughput (bidirectional, 128x128, 8 passes of 64 VRLs, cauchy-sum): "
      f"1 thread {t[0]['gathers_per_second']:.4g} gathers/s, 2 threads {t[1]['gathers_per_second']:.4g} gathers/s, "
      f"speedup {t[1]['gathers_per_second'] / t[0]['gathers_per_second']:.2f}")
PY
