#!/usr/bin/env bash
# The noise-free accuracy map on the medium-to-medium gather queries each scene really
# makes. For every scene and g: renders the scene's medium-to-medium gathers
# (vrl_render --gather m2m, 4 passes of 64 light paths) keeping about VRLIS_SCENE_QUERIES of
# its gather queries (--dump-queries, --dump-every chosen from a first render's gather
# count), runs vrlis_accuracy --queries on the dump, and writes docs/accuracy_scenes.md
# and copies the dumps to docs/accuracy_scenes/ (per-run JSON and tables stay in <outdir>).
#
#   tools/accuracy_scenes.sh [outdir=out/accuracy_scenes]
# Environment: VRLIS_SCENE_QUERIES
# (1000), VRLIS_SCENE_G ("-0.9 0.5 0.9"), VRLIS_SCENES_NO_DOCS=1 (leave docs/ alone).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/accuracy_scenes}
build=build
queries=${VRLIS_SCENE_QUERIES:-1000}
gs=${VRLIS_SCENE_G:-"-0.9 0.5 0.9"}
start=$(date +%s)

source tools/lib.sh
build_preset release vrl_render vrlis_accuracy
render="$build/examples/vrl_render"
accuracy="$build/bench/vrlis_accuracy"
mkdir -p "$out"

for scene in bidirectional room cube corner; do
  size=64
  [ "$scene" = cube ] && size=128  # the medium cube covers a small part of the image
  for g in $gs; do
    name="${scene}_g${g}"
    common=(--scene "$scene" --g "$g" --gather m2m --sampler cauchy-sum --effort off --width "$size" --height "$size" --spp 4 --vrls 64 --seed 1 --quiet
            --out "$out/$name.exr")
    "$render" "${common[@]}" >/dev/null
    gathers=$(/usr/bin/python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['gathers'])" "$out/$name.json")
    every=$(( gathers / queries > 1 ? gathers / queries : 1 ))
    "$render" "${common[@]}" --dump-queries "$out/$name.qlog" --dump-every "$every" >/dev/null
    echo "== $name: $gathers gathers, keeping one in $every"
    "$accuracy" --queries "$out/$name.qlog" --json "$out/$name.accuracy.json" | tee "$out/$name.accuracy.txt"
  done
done
rm -f "$out"/*.exr

model=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
machine="${model:-unknown CPU}, $(nproc) cores, $(uname -sr)"
command="tools/accuracy_scenes.sh${1:+ $1}"
/usr/bin/python3 bench/accuracy_scenes.py --dir "$out" --out "$out/accuracy_scenes.md" --machine "$machine" \
  --command "$command" --date "$(date -u '+%Y-%m-%d %H:%M UTC')" --seconds "$(( $(date +%s) - start ))" --queries "$queries"
if [ "${VRLIS_SCENES_NO_DOCS:-0}" != 1 ]; then
  cp "$out/accuracy_scenes.md" docs/accuracy_scenes.md
  mkdir -p docs/accuracy_scenes  # the dumps themselves: about 76 kB each
  cp "$out"/*.qlog docs/accuracy_scenes/
  echo "== updated docs/accuracy_scenes.md and docs/accuracy_scenes/*.qlog"
fi
