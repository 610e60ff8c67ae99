# Sourced by tools/main.sh and tools/decompose.sh, which start alike: split --publish from
# the arguments meant for vrl_compare, install what is missing, build vrl_compare.
# Sets `publish` (docs/compare with --publish, else empty) and `args` (every other argument).
prepare_vrl_compare() {
  publish=""
  args=()
  local a
  for a in "$@"; do
    if [ "$a" = "--publish" ]; then publish="docs/compare"; else args+=("$a"); fi
  done
  tools/deps.sh
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build --target vrl_compare -j "$(nproc)"
}
