# Sourced by the tools that build before they run: the one "install, configure, build".
# build_preset PRESET [TARGET...]: installs what is missing (tools/deps.sh), configures the
# CMake preset (build/ is always the `release` preset's: Release, warnings as errors) and
# builds the targets (everything when none is given).
build_preset() {
  local preset=$1
  shift
  tools/deps.sh
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$(nproc)" ${1:+--target "$@"}
}

# For tools/main.sh, tools/decompose.sh and tools/effort.sh: installs the charts' packages,
# splits --publish from the arguments meant for vrl_compare and builds vrl_compare. Sets
# `publish` (docs/compare with --publish, else empty) and `args` (every other argument).
prepare_vrl_compare() {
  tools/deps.sh charts
  publish=""
  args=()
  local a
  for a in "$@"; do
    if [ "$a" = "--publish" ]; then publish="docs/compare"; else args+=("$a"); fi
  done
  build_preset release vrl_compare vrlis_samplers  # vrlis_samplers: the sampler list (tools/samplers.py)
}
