#!/usr/bin/env bash
# Installs what is missing, builds everything (the `release` preset: Release, warnings as
# errors) and runs the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh
cmake --preset release
cmake --build --preset release -j "$(nproc)"
ctest --preset release -j "$(nproc)" "$@"
