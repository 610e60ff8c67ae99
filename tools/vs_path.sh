#!/usr/bin/env bash
# The VRL renderer's defaults against its own path tracer at equal time, per scene with a
# medium and surfaces (docs/renderer.md#bound-choice): bench/compare/vs_path.py over
# vrl_render, one thread, 48 x 48. --publish writes docs/compare/vs_path.md.
#   tools/vs_path.sh [--publish] [vs_path.py options: --seconds S --pairs P --scenes a,b --vrl-args A]
#   (defaults: 4 s per render, 4 pairs: ~6 minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
publish=""
args=()
for a in "$@"; do
  if [ "$a" = "--publish" ]; then publish=1; else args+=("$a"); fi
done
build_preset release vrl_render
out=out/vs_path
mkdir -p "$out"
/usr/bin/python3 bench/compare/vs_path.py build/examples/vrl_render "$out" --markdown "$out/vs_path.md" "${args[@]}"
if [ -n "$publish" ]; then
  {
    echo "# The VRL renderer against its own path tracer at equal time"
    echo
    echo "Generated $(date -u +%F) on $(uname -m), $(nproc) cores, by \`tools/vs_path.sh --publish${args[*]:+ ${args[*]}}\`."
    echo "Efficiency of \`vrl_render\`'s defaults over \`--integrator path\` at the same wall time, one thread,"
    echo "48 x 48: the path tracer's per-pixel variance over the VRL renderer's, each from the RMSE between"
    echo "two seeds' renders, pooled over seed pairs ([../renderer.md](../renderer.md#bound-choice))."
    echo
    cat "$out/vs_path.md"
  } >docs/compare/vs_path.md
  echo "wrote docs/compare/vs_path.md"
fi
