#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer: a separate
# clang++ build (build-asan, RelWithDebInfo, any sanitizer report is fatal), then ctest.
# Float division by zero is not enabled (-fsanitize=float-divide-by-zero is not part of
# "undefined"): IEEE inf and NaN are part of the library's numerics.
# Usage: tools/sanitize.sh [ctest arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" -DVRLIS_WERROR=ON \
  -DVRLIS_BUILD_EXAMPLES=OFF -DVRLIS_BUILD_BENCH=OFF
cmake --build build-asan -j "$(nproc)"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest --test-dir build-asan --output-on-failure -j "$(nproc)" "$@"
