#!/usr/bin/env bash
# ThreadSanitizer: builds the C APIs (libRoomCreatorLibrary.so), the layer and the simulated runtime with
# -fsanitize=thread (GCC; ROOMSENSE_SANITIZE=thread), only the targets the concurrency tests need, and runs the
# ctests labelled `concurrency`: both C APIs on 8 threads (tests/capi/capi_concurrency_test.cpp and the C test's
# thesis_parallel and handle_destroy_running) and the layer on 8 threads through the loader and the simulated
# runtime (tests/layer/concurrency_test.cpp). The pipeline runs on the CPU backend (Vulkan is not built: Mesa's
# lavapipe under TSan is noise, not our code). tests/tsan.supp suppresses reports inside third-party libraries
# only, never in our code; a report fails its test (TSan's exit code 66).
# Usage: scripts/tsan.sh [BUILD_DIR] [extra cmake arguments...]   (BUILD_DIR defaults to build-tsan)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-tsan}
shift || true

# setup.sh installs the packages, configures and builds its one target; the others follow.
ROOMSENSE_BUILD_TYPE=RelWithDebInfo ROOMSENSE_UNITY=1 ROOMSENSE_TARGET=capi_c_test scripts/setup.sh "$build_dir" \
  -DROOMSENSE_SANITIZE=thread -DROOMSENSE_BUILD_BENCH=OFF -DROOMSENSE_WITH_VULKAN=OFF "$@"
cmake --build "$build_dir" -j"$(nproc)" --target capi_concurrency_test layer_concurrency_tests

export TSAN_OPTIONS="suppressions=$PWD/tests/tsan.supp second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
export ROOMSENSE_BACKEND=cpu
export XDG_CACHE_HOME="$PWD/$build_dir/.cache"
ctest --test-dir "$build_dir" -L concurrency --output-on-failure -j"$(nproc)" --timeout 300
