#!/usr/bin/env bash
# The effort control's study: the default equal-time study (bidirectional and room,
# g in {-0.9, 0.5, 0.9}) of every sampler, each also with the effort control on
# (vrl_compare --with-effort), run with two seeds (~15 minutes each on a shared 2-core
# machine); bench/compare/effort.py tables both against the best fixed sampler.
#   tools/effort.sh            writes out/effort/seed1, out/effort/seed2 and prints the tables
#   tools/effort.sh --publish  also writes docs/compare/effort.md
# Other arguments go to vrl_compare, e.g. --scenes corner --g 0.5.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
prepare_vrl_compare "$@"
for seed in 1 2; do
  build/bench/compare/vrl_compare --with-effort --seed "$seed" --out "out/effort/seed$seed" "${args[@]}"
done
/usr/bin/python3 bench/compare/effort.py out/effort/seed1 out/effort/seed2 ${publish:+--publish "$publish/effort.md"} \
  --command "tools/effort.sh${*:+ $*}"
