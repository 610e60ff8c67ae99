#!/usr/bin/env bash
# Installs the Debian packages vrlis needs to build everything and run its tests, and with
# `charts` those its charts need too (only those missing; needs root or sudo). The charts'
# Python packages are most of a fresh machine's install time that the tests do not use.
# Usage: tools/deps.sh [charts]
set -euo pipefail
packages=(cmake ninja-build g++ clang libclang-rt-14-dev libfuzzer-14-dev libglm-dev libembree-dev libopenexr-dev
          catch2 libbenchmark-dev libtbb-dev libboost-math-dev libpcg-cpp-dev libcli11-dev libstb-dev
          nlohmann-json3-dev)
case "${1:-}" in
  "") ;;
  charts) packages+=(python3-matplotlib python3-numpy) ;;
  *) echo "usage: tools/deps.sh [charts]" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "installing: ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
