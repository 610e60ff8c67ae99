#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs the equal-time study of every
# camera sampler (default: the bidirectional scene and the room, g in {-0.9, 0.5, 0.9}: 6 studies
# x 6 samplers x at least 8 s, 8-10 minutes on a shared 2-core machine); prints the table with
# 95% intervals and what each study could resolve, and writes charts under out/compare.
#   tools/main.sh            the default study
#   tools/main.sh --full     every scene, g in {-0.9, -0.5, 0, 0.5, 0.9}, 12 s per sampler (~30 min)
#   tools/main.sh --publish  also write docs/compare/results.md, its charts and the README table
# Other arguments go to vrl_compare (see build/bench/compare/vrl_compare --help), e.g. --seed 2.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
prepare_vrl_compare "$@"
out=out/compare
build/bench/compare/vrl_compare --out "$out" "${args[@]}"
/usr/bin/python3 bench/compare/plot.py "$out" ${publish:+--publish "$publish"} --command "tools/main.sh${*:+ $*}"
echo "efficiency chart: $out/efficiency.png; images: $out/<scene>_g<g>/"
