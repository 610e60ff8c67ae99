#!/usr/bin/env bash
# Where the noise lives: per scene, the shares of per-pass variance and of time for each
# part of light transport, and step one versus step two inside the medium-to-medium gather
# (vrl_compare --decompose; about 5 minutes for the six scenes on 2 cores). Writes
# out/compare/decompose/; with --publish also docs/compare/decomposition.md and its charts.
# Other arguments go to vrl_compare (e.g. --scenes room --decompose-seconds 60).
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
prepare_vrl_compare "$@"
out=out/compare
build/bench/compare/vrl_compare --decompose --out "$out" "${args[@]}" >/dev/null
/usr/bin/python3 bench/compare/plot.py "$out" --decompose ${publish:+--publish "$publish"} --command "tools/decompose.sh${*:+ $*}"
echo "page and charts: $out/decompose/decomposition.md"
