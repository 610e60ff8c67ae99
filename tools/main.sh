#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs the equal-time comparison of
# every camera sampler (default: the bidirectional scene and the room, g in {-0.9, 0.5, 0.9},
# about 5 minutes on 2 cores); prints the summary table and writes charts under out/compare.
#   tools/main.sh            the default comparison
#   tools/main.sh --full     every scene, g in {-0.9, -0.5, 0, 0.5, 0.9}, longer budgets
#   tools/main.sh --publish  also copy charts and table into docs/compare (for the README)
# Other arguments go to vrl_compare (see build/compare/vrl_compare --help).
set -euo pipefail
cd "$(dirname "$0")/.."
publish=""
args=()
for a in "$@"; do
  if [ "$a" = "--publish" ]; then publish="docs/compare"; else args+=("$a"); fi
done
tools/deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target vrl_compare -j "$(nproc)"
out=out/compare
build/compare/vrl_compare --budget 4 --out "$out" "${args[@]}"
/usr/bin/python3 compare/plot.py "$out" ${publish:+--publish "$publish"} --command "tools/main.sh $*"
echo "charts and images: $out/<scene>_g<g>/"
