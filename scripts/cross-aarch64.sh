#!/usr/bin/env bash
# Cross-builds the CPU side (scene/, softrender/, compare/ and their GL-free tests;
# TWINRASTER_CPU_ONLY) for 64-bit ARM with Debian's cross compiler, and runs the tests under
# qemu-user, so the NEON and scalar paths of the one shading source are built and checked on
# a machine with no ARM hardware. CI runs it as its own stage (.ci/run).
#
#   scripts/cross-aarch64.sh            install what is missing, configure, build, test
#
# What it installs (idempotent: nothing when everything is there; apt is run as root, or
# through sudo):
#   - the arm64 architecture in dpkg (multiarch), so arm64 library packages install beside
#     the x86-64 ones: libhwy-dev:arm64, libtinyobjloader-dev:arm64, libstb-dev:arm64,
#     libgtest-dev:arm64 (each Multi-Arch: same, at the amd64 package's version), which pull
#     in libc6:arm64 and libstdc++6:arm64 at the paths an arm64 machine has them;
#   - g++-aarch64-linux-gnu (the cross compiler), qemu-user (qemu-aarch64), and the
#     arch-independent headers libglm-dev and nlohmann-json3-dev.
# qemu finds the arm64 loader at /lib/ld-linux-aarch64.so.1 (libc6:arm64), so it needs no
# QEMU_LD_PREFIX; the toolchain file (cmake/aarch64-linux-gnu.cmake) sets qemu-aarch64 as
# CMake's cross-compiling emulator, which gtest_discover_tests and ctest use.
#
# Environment:
#   CROSS_BUILD_DIR  build folder (default build-aarch64)
#   CROSS_JOBS       build parallelism (default nproc)
#   CROSS_WERROR     ON|OFF: -Werror for the project's code (default ON under CI, else OFF)
#   CROSS_TESTS      ctest -R regex of the tests to run under qemu (default: all of them)
#   TWINRASTER_REQUIRE_CPU_ISAS  Highway targets that must be present (default neon,scalar)
#   CROSS_BUILD_TYPE CMake build type (default Release)
set -euo pipefail
cd "$(dirname "$0")/.."

build=${CROSS_BUILD_DIR:-build-aarch64}
jobs=${CROSS_JOBS:-$(nproc 2>/dev/null || echo 2)}
build_type=${CROSS_BUILD_TYPE:-Release}
case "${CI:-}" in
  ""|false|0) werror_default=OFF ;;
  *) werror_default=ON ;;
esac
werror=${CROSS_WERROR:-$werror_default}
# ctest -R regex; empty runs every GL-free test. Measured on the 2-core CI machine: all of
# them take about 4 minutes under qemu at -j2, 80 % of it the fast-path tests (FastPath*:
# every suite scene and every view on NEON and on scalar against the teaching path), so the
# rest, about 50 s, is kept too.
tests=${CROSS_TESTS:-}
# The fast-path tests fail, rather than skip, when a target listed here is not compiled in or
# not run (test_fast_path.cpp, FastPathTargets.RequiredTargetsArePresent): NEON must be there
# on aarch64, and Highway's portable target (SCALAR; EMU128 with GCC >= 12.3).
export TWINRASTER_REQUIRE_CPU_ISAS=${TWINRASTER_REQUIRE_CPU_ISAS:-neon,scalar}

arch=arm64
host_packages=(g++-aarch64-linux-gnu qemu-user cmake pkg-config libglm-dev nlohmann-json3-dev)
target_packages=(libhwy-dev libtinyobjloader-dev libstb-dev libgtest-dev)

# ---- install (idempotent) ----
if [ "$(id -u)" -eq 0 ]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo)
else
  sudo_cmd=(false)  # only reached when something is missing: reported below
fi

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }

missing=()
for p in "${host_packages[@]}"; do installed "$p" || missing+=("$p"); done
for p in "${target_packages[@]}"; do installed "$p:$arch" || missing+=("$p:$arch"); done

if [ ${#missing[@]} -gt 0 ]; then
  if [ "${sudo_cmd[0]:-}" = false ]; then
    echo "cross-aarch64: missing packages (${missing[*]}) and not root, no sudo" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  if ! dpkg --print-foreign-architectures | grep -qx "$arch"; then
    echo "cross-aarch64: adding the $arch architecture to dpkg (multiarch)"
    "${sudo_cmd[@]}" dpkg --add-architecture "$arch"
  fi
  echo "cross-aarch64: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "cross-aarch64: all $(( ${#host_packages[@]} + ${#target_packages[@]} )) packages present"
fi

# ---- configure, build ----
start=$(date +%s)
echo "cross-aarch64: configuring $build ($build_type, TWINRASTER_CPU_ONLY, -Werror $werror)"
cmake -S . -B "$build" --toolchain cmake/aarch64-linux-gnu.cmake \
  -DCMAKE_BUILD_TYPE="$build_type" -DTWINRASTER_CPU_ONLY=ON -DTWINRASTER_WERROR="$werror" >/dev/null
# The test binaries are discovered (gtest_discover_tests) by running them under qemu-aarch64
# at build time, so a binary that does not start on arm64 already fails here.
cmake --build "$build" -j "$jobs"
built=$(date +%s)
echo "cross-aarch64: build took $(( built - start )) s"

# ---- run under qemu ----
ctest_args=(--test-dir "$build" --output-on-failure -j "$jobs" --timeout 900)
[ -n "$tests" ] && ctest_args+=(-R "$tests")
echo "cross-aarch64: running the tests under $(grep -m1 '^TWINRASTER_QEMU_AARCH64:' "$build/CMakeCache.txt" | cut -d= -f2)" \
  "(TWINRASTER_REQUIRE_CPU_ISAS=$TWINRASTER_REQUIRE_CPU_ISAS)"
ctest "${ctest_args[@]}"
echo "cross-aarch64: tests under qemu took $(( $(date +%s) - built )) s"
