#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs the equal-time study of every
# camera sampler and FullProduct with VrlMarginal as step one (default: the bidirectional scene
# and the room, g in {-0.9, 0.5, 0.9}: 6 studies x 7 samplers x at least 8 s, about 11 minutes
# on a shared 2-core machine; the effort control's study is tools/effort.sh); prints the table with
# 95% intervals and what each study could resolve, and writes charts under out/compare.
#   tools/main.sh            the default study
#   tools/main.sh --full     every scene, g in {-0.9, -0.5, 0, 0.5, 0.9}, 12 s per sampler (~60 min)
#   tools/main.sh --publish  also write docs/compare/results.md, its charts and the README table
#   tools/main.sh --vrl-only the image of the two VRL gathers alone, as the thesis measured (out/compare-vrl;
#                            with --publish: docs/compare/vrl_only.md, thesis_claims.md, rmse_time_*.png)
#   tools/main.sh --rmse-all an RMSE-against-time chart for every study, not only bidirectional g = -0.9
# Other arguments go to vrl_compare (see build/bench/compare/vrl_compare --help), e.g. --seed 2.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
prepare_vrl_compare "$@"
out=out/compare
study=() plot=()
for a in "${args[@]}"; do
  case "$a" in
    --rmse-all) plot+=("$a") ;;
    --vrl-only) out=out/compare-vrl; study+=("$a") ;;
    *) study+=("$a") ;;
  esac
done
build/bench/compare/vrl_compare --out "$out" "${study[@]}"
/usr/bin/python3 bench/compare/plot.py "$out" ${publish:+--publish "$publish"} "${plot[@]}" --command "tools/main.sh${*:+ $*}"
echo "efficiency chart: $out/efficiency.png; images: $out/<scene>_g<g>/"
