#!/usr/bin/env bash
# Installs what is missing, builds everything (the `release` preset: Release, warnings as
# errors) and runs the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/lib.sh
build_preset release
ctest --preset release -j "$(nproc)" "$@"
