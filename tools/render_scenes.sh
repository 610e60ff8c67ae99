#!/usr/bin/env bash
# Renders the comparison scenes into docs/scenes/ (PNG previews and JSON summaries
# committed; EXRs kept out of git) and measures VRL gathers per second with 1 and 2
# threads, and writes the gallery of docs/results.md (docs/scenes/gallery.png).
# Usage: tools/render_scenes.sh [seconds per scene, default 60; bidirectional x4, room x12, corner x9,
# cloud x2, fog x8] [size, default 192]
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_SCENE=${1:-60}
SIZE=${2:-192}
source tools/lib.sh
build_preset release vrl_render >/dev/null
BIN=build/examples/vrl_render
OUT=docs/scenes
mkdir -p "$OUT"
common=(--width "$SIZE" --height "$SIZE" --vrls 64 --seed 1 --sampler cauchy-sum --quiet)
# Scenes whose path-traced parts converge slowly (room, corner), whose passes are long (fog) or
# whose VRLs are the whole image (bidirectional, cloud) get a multiple of the time, so that no
# preview shows speckle or a single VRL's streak at its published size (about 45 minutes).
declare -A factor=([bidirectional]=4 [room]=12 [corner]=9 [cloud]=2 [fog]=8)
for scene in bidirectional room cube corner cloud fog; do
  "$BIN" --scene "$scene" "${common[@]}" --time $((SECONDS_PER_SCENE * ${factor[$scene]:-1})) \
    --out "$OUT/$scene.exr" >/dev/null
done
for gather in m2m m2s; do
  "$BIN" --scene corner --gather "$gather" "${common[@]}" --time "$SECONDS_PER_SCENE" \
    --out "$OUT/corner-$gather.exr" >/dev/null
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
# The gallery of docs/results.md: the six scenes side by side.
import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg
import matplotlib.pyplot as plt
names = ["bidirectional", "room", "cube", "corner", "cloud", "fog"]
fig, axes = plt.subplots(1, len(names), figsize=(2 * len(names), 2.3))
for ax, s in zip(axes, names):
    ax.imshow(mpimg.imread(f"{out}/{s}.png"))
    ax.set_title(s, fontsize=10)
    ax.axis("off")
fig.tight_layout()
fig.savefig(f"{out}/gallery.png", dpi=100)
t = [json.load(open(f"/tmp/vrl_throughput_{n}.json")) for n in (1, 2)]
print()
print(f"Throughput (bidirectional, 128x128, 8 passes of 64 VRLs, cauchy-sum): "
      f"1 thread {t[0]['gathers_per_second']:.4g} gathers/s, 2 threads {t[1]['gathers_per_second']:.4g} gathers/s, "
      f"speedup {t[1]['gathers_per_second'] / t[0]['gathers_per_second']:.2f}")
PY
