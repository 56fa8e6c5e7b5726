#!/usr/bin/env bash
# Installs the Debian 12 packages roomsense needs (only those missing), then configures and builds.
# Usage: scripts/setup.sh [BUILD_DIR] [extra cmake arguments...]; ROOMSENSE_TARGET=NAME builds one target;
# ROOMSENSE_EXTRA_PACKAGES="a b" installs more (the fuzzing and TSan scripts' compilers); ROOMSENSE_WINDOWS=1 adds
# the Windows build's (MinGW-w64, Wine, GoogleTest's sources: scripts/windows.sh). ROOMSENSE_UNITY=1 compiles each
# target's files together in batches (CMake's unity build): the sanitizer, fuzzing and Windows builds, which CI makes
# besides the README's, so that .ci/run fits its time. The README's build compiles each file alone, which keeps every
# file's includes complete and its own names its own (the extensions' files compile alone in both: their CMakeLists).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true

packages=(cmake g++ ninja-build pkg-config
          libopenxr-dev libopenxr-loader1 openxr-layer-corevalidation libopenxr-utils
          libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools glslang-dev
          libglm-dev nlohmann-json3-dev libassimp-dev libtinyobjloader-dev libgtest-dev libbenchmark-dev
          libxml2-dev  # libxml2: tests only (plan.svg is checked with a real XML parser)
          mono-mcs mono-runtime  # tests only: the C# binding (bindings/csharp/) compiled and run under Mono
          ${ROOMSENSE_EXTRA_PACKAGES:-})
if [ -n "${ROOMSENSE_WINDOWS:-}" ]; then
  packages+=(g++-mingw-w64-x86-64-posix wine wine64 googletest)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

unity=()
[ -n "${ROOMSENSE_UNITY:-}" ] && unity=(-DCMAKE_UNITY_BUILD=ON)
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE="${ROOMSENSE_BUILD_TYPE:-Release}" "${unity[@]}" "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)" ${ROOMSENSE_TARGET:+--target "$ROOMSENSE_TARGET"}
