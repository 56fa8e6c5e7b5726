#!/usr/bin/env bash
# The Windows build, checked on Linux: cross-compiles core, both C APIs, the CLI and the OpenXR layer with
# MinGW-w64 (cmake/toolchains/mingw-w64-x86_64.cmake), runs their tests under Wine, and packs the ZIP a
# Windows user unpacks (build-win/packages/roomsense-<version>-win64.zip).
# Usage: scripts/windows.sh [BUILD_DIR] [extra cmake arguments...]   (default build-win)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-win}
shift || true
ROOMSENSE_WINDOWS=1 ROOMSENSE_UNITY=1 scripts/setup.sh "$build_dir" -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/toolchains/mingw-w64-x86_64.cmake" "$@"

echo "== windows: the tests of core, the C APIs, the CLI and the layer DLL under $(wine --version 2>/dev/null)"
# Wine, with tests starting in parallel, now and then fails to start a process: a test's own (it fails with no
# output: PlyReader.MissingVertexLinesAreAnError, Areas.SearchingNothingFindsNothing) or a program the test
# starts (Cli.HugeNumbersArePrintedCompactly: cmd.exe's "not recognized" for roomsense.exe). Each passed alone
# and in a hundred repeats and more. A test runs again after a failure, three times at most; one that fails
# three times fails the build. A test that hangs fails after 180 s (the slowest takes some 30 s under Wine).
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" --repeat until-pass:3 --timeout 180 |
  grep -vE '^ +Start |^ *[0-9]+/[0-9]+ Test +#'
echo "== windows: what the DLLs export and need, and the layer's registration (the checks' own words)"
ctest --test-dir "$build_dir" -R '^(capi\.exported_symbols|capi\.shared_dependencies|windows\.)' -V |
  sed -nE 's/^[0-9]+: (-- )?//p' | grep -vE '^(Test command|Working Directory|Environment variables|Test timeout)' |
  cut -c1-200
echo "== windows: the ZIP (cpack -G ZIP)"
(cd "$build_dir" && cpack -G ZIP >/dev/null)
zip=$(ls "$build_dir"/packages/roomsense-*-win64.zip)
listing=$(cmake -E tar tf "$zip")
for f in bin/RoomCreatorLibrary.dll bin/roomsense.exe bin/XrApiLayer_roomsense.dll \
         bin/XR_APILAYER_ROOMSENSE_room_understanding.json bin/register_layer.cmd \
         include/roomsense/roomsense.h include/roomsense/RoomCreatorLibrary.h \
         include/openxr/XR_EXTX_room_understanding.h lib/libRoomCreatorLibrary.dll.a lib/cmake/roomsense/roomsenseConfig.cmake; do
  grep -qE "/$f\$" <<<"$listing" || { echo "windows: $zip lacks $f" >&2; exit 1; }
done
echo "$zip: $(wc -l <<<"$listing") files, with the DLLs, roomsense.exe, the layer's manifest and register_layer.cmd"
