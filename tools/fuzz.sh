#!/usr/bin/env bash
# Builds the libFuzzer target fuzz/fuzz_samplers.cpp (the `fuzz` preset: clang++,
# -fsanitize=fuzzer,address,undefined) and runs it on the committed corpus in fuzz/corpus for
# a fixed time; new interesting inputs go to build-fuzz/corpus (merge them into fuzz/corpus
# with -merge=1 to keep them).
# fuzz/regressions holds one input per class of violation found so far; the test suite replays
# them and the corpus as a gate (ctest fuzz_regressions, fuzz_corpus); `tools/fuzz.sh
# regressions` replays them one by one and lists the ones that still fail, for triage.
# Usage: tools/fuzz.sh [seconds=60] [extra libFuzzer flags...] | tools/fuzz.sh regressions
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"; shift || true
out=build-fuzz
source tools/lib.sh
build_preset fuzz >/dev/null
mkdir -p "$out/corpus" "$out/artifacts"
bin="$out/fuzz/fuzz_samplers"
if [ "$seconds" = regressions ]; then
  failed=0
  for f in fuzz/regressions/*; do
    if msg=$("$bin" "$f" 2>&1); then echo "fixed:   $(basename "$f")"; else
      failed=$((failed + 1)); echo "FAILS:   $(basename "$f"): $(echo "$msg" | grep -m1 -E 'CONTRACT|runtime error|ERROR')"; fi
  done
  echo "fuzz regressions: $failed of $(ls fuzz/regressions | wc -l) still fail"
  [ "$failed" -eq 0 ]; exit
fi
log="$out/fuzz.log"
set +e
"$bin" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$out/artifacts/" \
  "$@" "$out/corpus" fuzz/corpus 2>&1 | tee "$log" | grep -E '^(#[0-9]+ *(INITED|DONE|pulse)|CONTRACT|==|SUMMARY|stat::number_of_executed_units)' 
rc=${PIPESTATUS[0]}
set -e
runs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}' | tail -1)
echo "fuzz: ${runs:-?} executions in ${seconds} s, exit code $rc (log: $log)"
exit "$rc"
