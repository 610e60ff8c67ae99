#!/usr/bin/env bash
# The library's test suite under AddressSanitizer and UndefinedBehaviorSanitizer: the
# `sanitize` preset (clang++, RelWithDebInfo, any sanitizer report is fatal; build-asan),
# then ctest. Float division by zero is not enabled (-fsanitize=float-divide-by-zero is not
# part of "undefined"): IEEE inf and NaN are part of the library's numerics.
# Usage: tools/sanitize.sh [ctest arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
build_preset sanitize
ctest --preset sanitize -j "$(nproc)" "$@"
