#!/usr/bin/env bash
# The library's test suite under AddressSanitizer and UndefinedBehaviorSanitizer: the
# `sanitize` preset (clang++, RelWithDebInfo with line tables only: the reports' files and
# lines without the build time of full debug information; any sanitizer report is fatal;
# build-asan), then ctest. Float division by zero is not enabled
# (-fsanitize=float-divide-by-zero is not part of "undefined"): IEEE inf and NaN are part of
# the library's numerics. The heaviest statistical tests run on a quarter of their samples and
# configurations (the sanitize test preset's VRLIS_TEST_DIVISOR, tests/support/divisor.hpp):
# this run is after memory errors and undefined behaviour, which every test and code path still
# meets; the release run keeps their full strength. Prints the build's and the tests' wall and
# CPU times (CI's budget: .ci/run).
# Usage: tools/sanitize.sh [ctest arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
TIMEFORMAT="== sanitize build: %0R s wall, %0U s user + %0S s sys"
time build_preset sanitize
TIMEFORMAT="== sanitize tests: %0R s wall, %0U s user + %0S s sys"
time ctest --preset sanitize -j "$(nproc)" "$@"
