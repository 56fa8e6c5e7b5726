#!/usr/bin/env bash
# The README's second command: set up, build, and run every test.
# Usage: scripts/test.sh [BUILD_DIR] [extra cmake arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
scripts/setup.sh "$build_dir" "$@"
# Mesa's shader cache stays in the build tree, not in $HOME.
export XDG_CACHE_HOME="$PWD/$build_dir/.cache"
# A test that hangs fails after 300 s (tests with a TIMEOUT of their own keep it; the slowest, under ASan, takes
# some 40 s) rather than holding the run until CI's own limit.
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" --timeout 300
