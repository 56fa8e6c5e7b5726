#!/usr/bin/env bash
# The Debian packages end to end, as CI runs them: configure BUILD_DIR for /usr and build it, cpack -G DEB,
# lintian (no errors allowed), apt-get install ./*.deb on this machine, the demo and the CLI from the installed
# files, a consumer built against roomsense-dev with find_package(roomsense) and with pkg-config, then
# apt-get purge and a check that no file is left behind. Needs root or sudo; installs the implicit layer
# system-wide while it runs, so run nothing else that uses OpenXR meanwhile.
# Usage: scripts/package.sh [BUILD_DIR] [extra cmake arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
source=$PWD
build_dir=${1:-build}
shift || true
ROOMSENSE_EXTRA_PACKAGES="lintian ${ROOMSENSE_EXTRA_PACKAGES:-}" scripts/setup.sh "$build_dir" -DCMAKE_INSTALL_PREFIX=/usr "$@"
build=$(cd "$build_dir" && pwd)
sudo=""
[ "$(id -u)" -eq 0 ] || sudo=sudo
work=$(mktemp -d)
installed=()
cleanup() {
  if ((${#installed[@]})); then
    DEBIAN_FRONTEND=noninteractive $sudo apt-get purge -y -qq "${installed[@]}" >/dev/null 2>&1 || true
  fi
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "package: FAILED: $*" >&2; exit 1; }

echo "== cpack -G DEB in $build_dir"
rm -rf "$build/packages"
(cd "$build" && cpack -G DEB 2>&1) | grep -E "^CPack: - package:" | sed "s|$build/||"
debs=("$build"/packages/*.deb)
names=()
for deb in "${debs[@]}"; do names+=("$(dpkg-deb -f "$deb" Package)"); done
((${#names[@]} == 5)) || fail "expected 5 packages, got ${names[*]}"

echo "== lintian (errors fail; the warnings left are explained in packaging/README.md)"
lintian --tag-display-limit 0 "${debs[@]}" 2>/dev/null | tee "$work/lintian.txt" || true
! grep -q "^E:" "$work/lintian.txt" || fail "lintian reports errors"

echo "== apt-get install ./*.deb"
snapshot() { find /usr /etc /opt -xdev 2>/dev/null | LC_ALL=C sort; }
snapshot >"$work/files.before"
dpkg-query -W -f='${Package}\n' | LC_ALL=C sort >"$work/packages.before"
installed=("${names[@]}")
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${debs[@]}" >"$work/apt.log" 2>&1 || { cat "$work/apt.log"; fail "apt-get install"; }
dpkg-query -W -f='${Package}\n' | LC_ALL=C sort >"$work/packages.after"
mapfile -t pulled < <(comm -13 "$work/packages.before" "$work/packages.after")
installed=("${pulled[@]}")
echo "installed: ${pulled[*]}"
for name in "${names[@]}"; do
  dpkg -L "$name" | grep -E "\.(so[.0-9]*|json|pc|cmake)$|/bin/" | sed "s/^/  $name: /"
done

echo "== the installed files name no build or source folder, and carry no RPATH"
mapfile -t files < <(for name in "${names[@]}"; do dpkg -L "$name"; done | while read -r f; do [ -f "$f" ] && echo "$f"; done)
for f in "${files[@]}"; do
  if grep -qF "$source" "$f"; then fail "$f names the source or build folder ($source)"; fi
  if readelf -d "$f" 2>/dev/null | grep -qE "RPATH|RUNPATH"; then fail "$f has an RPATH"; fi
done
echo "ok: ${#files[@]} files"

echo "== roomsense-demo from /usr/bin (a clean environment, run from an empty folder)"
demo=$(cd "$work" && env -i PATH=/usr/bin:/bin HOME="$work" roomsense-demo --output "$work/demo-output" 2>&1) ||
  { echo "$demo"; fail "roomsense-demo"; }
grep -E "^(runtime|layer) " <<<"$demo"
grep -qE "^layer +/usr/lib/[^ ]*/roomsense/libXrApiLayer_roomsense\.so" <<<"$demo" || fail "the demo did not load the installed layer"
grep -m3 -E "^ +[0-9]+  wall +(large|medium|small) +(close|distance|none) " <<<"$demo" || fail "the demo printed no wall areas"
[ -s "$work/demo-output/analysis.json" ] || fail "the demo wrote no analysis.json"
if grep -qF "$source" <<<"$demo"; then fail "the demo's output names the build or source folder"; fi
env -i PATH=/usr/bin:/bin roomsense analyze synthetic:default | awk 'NR <= 3'

echo "== a consumer of roomsense-dev: find_package(roomsense)"
cmake -S tests/package -B "$work/consumer" -G Ninja >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/consumer"
echo "== a consumer of roomsense-dev: pkg-config"
echo "pkg-config --cflags --libs roomsense: $(pkg-config --cflags --libs roomsense)"
# shellcheck disable=SC2046
cc -std=c11 -o "$work/consumer-pc" tests/package/consumer.c $(pkg-config --cflags --libs roomsense) -lm
"$work/consumer-pc"

echo "== apt-get purge, and nothing left behind"
DEBIAN_FRONTEND=noninteractive $sudo apt-get purge -y -qq "${installed[@]}" >/dev/null 2>&1 || fail "apt-get purge"
installed=()
snapshot >"$work/files.after"
if ! diff "$work/files.before" "$work/files.after" >"$work/files.diff"; then
  cat "$work/files.diff"
  fail "files differ after the purge"
fi
echo "ok: the same $(wc -l <"$work/files.after") paths under /usr, /etc and /opt as before"
