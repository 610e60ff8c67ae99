#!/usr/bin/env bash
# Two default studies with different seeds (tools/main.sh --seed 1, then --seed 2, the
# references cached by the first), and whether they give the same verdicts; writes
# docs/compare/two_runs.md. About twice the default study's time.
#   tools/two_runs.sh            run both, then compare
#   tools/two_runs.sh --compare  compare the runs kept in out/compare_seed1 and out/compare_seed2
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" != --compare ]; then
  for seed in 1 2; do
    start=$SECONDS
    tools/main.sh --seed "$seed"
    rm -rf "out/compare_seed$seed" && cp -r out/compare "out/compare_seed$seed"
    echo $((SECONDS - start)) >"out/compare_seed$seed/seconds.txt"
  done
fi
{
  echo "# Two default runs with different seeds"
  echo
  echo "Generated $(date -u +%F) by \`tools/two_runs.sh\`: \`tools/main.sh --seed 1\`, then \`--seed 2\` on the same machine. Per study, the verdict and the sampler called best or the samplers tied with the winner ([README.md](README.md#the-verdict) says how they are decided)."
  echo
  for seed in 1 2; do
    [ ! -f "out/compare_seed$seed/seconds.txt" ] || printf "Seed %s took %s s (build included).\n\n" "$seed" "$(cat "out/compare_seed$seed/seconds.txt")"
  done
  /usr/bin/python3 bench/compare/two_runs.py out/compare_seed1 out/compare_seed2
} >docs/compare/two_runs.md.new
mv docs/compare/two_runs.md.new docs/compare/two_runs.md
echo "wrote docs/compare/two_runs.md"
