#!/usr/bin/env bash
# Installs exactly the Debian 12 packages twinraster needs to build, test and run.
# Idempotent: packages already present are skipped, and apt is not touched at all
# when nothing is missing. Works as root; uses sudo otherwise.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglfw3-dev libglm-dev python3-glad libimgui-dev libosmesa6-dev
  libegl-dev libegl-mesa0    # EGL headers, and Mesa's EGL (surfaceless llvmpipe) opened at run time
  libtinyobjloader-dev libstb-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libbenchmark-dev
  libhwy-dev                 # Google Highway: the fast path's portable SIMD
  libembree-dev              # Intel Embree: the ray-traced references (the build works without it)
  xvfb xauth xdotool         # xdotool drives the desktop app in tests/gui/test_gui_scripted
  imagemagick                # writes the BMP, TGA and DDS files the texture tests read
  clang libclang-rt-14-dev   # libFuzzer and clang's sanitizers (scripts/run-fuzzers.sh)
  lld                        # LLVM's linker: the test executables link in a fifth of GNU ld's time
  assimp-testmodels          # real-world OBJ files for fuzz/test_real_world_models.cpp
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo)
else
  echo "install-deps: missing packages (${missing[*]}) and not root, no sudo" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
