# Cross build for 64-bit ARM (aarch64) on a Debian 12 x86-64 machine, with Debian's cross
# compiler (g++-aarch64-linux-gnu) and the arm64 builds of the libraries installed side by
# side through multiarch (dpkg --add-architecture arm64; libhwy-dev:arm64 and friends land in
# /usr/lib/aarch64-linux-gnu). scripts/cross-aarch64.sh installs all of it and uses this file:
#
#   cmake -S . -B build-aarch64 --toolchain cmake/aarch64-linux-gnu.cmake -DTWINRASTER_CPU_ONLY=ON
#
# Only the CPU side (TWINRASTER_CPU_ONLY) is meant to be built this way. Test executables run
# under qemu-user (CMAKE_CROSSCOMPILING_EMULATOR), both for gtest_discover_tests at build time
# and for ctest.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(TWINRASTER_CROSS_TRIPLET aarch64-linux-gnu)
set(CMAKE_C_COMPILER ${TWINRASTER_CROSS_TRIPLET}-gcc)
set(CMAKE_CXX_COMPILER ${TWINRASTER_CROSS_TRIPLET}-g++)
# Multiarch: find_package and find_library look in /usr/lib/aarch64-linux-gnu (arm64's
# libraries and CMake package files) and never in x86-64's /usr/lib/x86_64-linux-gnu.
# Arch-independent headers (GLM, nlohmann-json, Highway's, stb's) are shared from /usr/include.
set(CMAKE_LIBRARY_ARCHITECTURE ${TWINRASTER_CROSS_TRIPLET})

# pkg-config (Highway, stb): arm64's .pc files only, never the build machine's.
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/${TWINRASTER_CROSS_TRIPLET}/pkgconfig:/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")

# Run target executables under qemu-user. The arm64 loader and C/C++ runtime come from the
# multiarch packages (libc6:arm64, libstdc++6:arm64, pulled in by the -dev packages), at the
# paths an arm64 machine has them (/lib/ld-linux-aarch64.so.1, /lib/aarch64-linux-gnu), so
# qemu needs no -L / QEMU_LD_PREFIX and the binaries see one consistent glibc.
find_program(TWINRASTER_QEMU_AARCH64 NAMES qemu-aarch64 qemu-aarch64-static)
if(TWINRASTER_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${TWINRASTER_QEMU_AARCH64})
endif()
