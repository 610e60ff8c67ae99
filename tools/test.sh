#!/usr/bin/env bash
# Installs what is missing, builds everything (the `release` preset: Release, warnings as
# errors) and runs the whole test suite with ctest. Prints the build's and the tests' wall
# and CPU times (CI's budget: .ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
TIMEFORMAT="== release build: %0R s wall, %0U s user + %0S s sys"
time build_preset release
TIMEFORMAT="== release tests: %0R s wall, %0U s user + %0S s sys"
time ctest --preset release -j "$(nproc)" "$@"
