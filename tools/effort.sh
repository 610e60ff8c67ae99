#!/usr/bin/env bash
# The effort control's study: every sampler of the equal-time study, each also with the effort
# control on (vrl_compare --with-effort), in every scene at every g of the --full study: the
# default study (bidirectional and room, g in {-0.9, 0.5, 0.9}) with seeds 1 and 2, then cube,
# corner, cloud and fog at g in {-0.9, 0.5}, then every scene at its remaining g, with seed 1
# (~95 minutes at --budget 4 on a shared 2-core machine); bench/compare/effort.py tables every
# method against the best fixed published sampler.
#   tools/effort.sh            writes out/effort/{seed1,seed2,other,rest,rest-other} and prints the tables
#   tools/effort.sh --publish  also writes docs/compare/effort.md, with every method's cells over the
#                              page it replaces
# Other arguments go to every vrl_compare run, e.g. --budget 4. Every run renders at least 8
# passes per replicate: the control decides from its second pass on a price that settles over
# the next few, and fog's passes are so long that the budget alone gives it two.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
prepare_vrl_compare "$@"
study=(build/bench/compare/vrl_compare --with-effort --min-passes 8)
for seed in 1 2; do
  "${study[@]}" --seed "$seed" --out "out/effort/seed$seed" "${args[@]}"
done
"${study[@]}" --scenes cube,corner,cloud,fog --g -0.9,0.5 --seed 1 --out out/effort/other "${args[@]}"
"${study[@]}" --scenes bidirectional,room --g -0.5,0 --seed 1 --out out/effort/rest "${args[@]}"
"${study[@]}" --scenes cube,corner,cloud,fog --g -0.5,0,0.9 --seed 1 --out out/effort/rest-other "${args[@]}"
/usr/bin/python3 bench/compare/effort.py out/effort/seed1 out/effort/seed2 out/effort/other out/effort/rest out/effort/rest-other \
  ${publish:+--publish "$publish/effort.md" --previous "$publish/effort.md"} --command "tools/effort.sh${*:+ $*}"
