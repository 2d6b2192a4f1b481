#!/usr/bin/env bash
# Installs exactly the Debian 12 packages twinraster needs to build, test and run.
# Idempotent: packages already present are skipped, and apt is not touched at all
# when nothing is missing. Works as root; uses sudo otherwise.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build   # the presets build with Ninja (Makefile says why)
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
  chromium                   # the browser tests (tests/browser) drive Debian's chromium; no browser download
)
# Node.js runs the browser tests' Playwright; a machine that has a node of its own keeps it.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# The browser tests' npm packages (playwright-core alone, pinned in tests/browser's lock file),
# into tests/browser/node_modules: nothing is fetched at build or test time.
install_browser_packages() {
  local dir
  dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/browser"
  if [ -d "$dir/node_modules/playwright-core" ]; then
    return 0
  fi
  echo "install-deps: npm ci in $dir (playwright-core, for the browser tests)"
  (cd "$dir" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
}

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  install_browser_packages
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
install_browser_packages
