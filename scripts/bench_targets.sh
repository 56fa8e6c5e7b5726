#!/usr/bin/env bash
# Issue 19's targets against this tree's roomsense_bench, as one table: each target, the case that measures it, the
# median of ROUNDS runs and their range (lowest to highest), and whether the median meets it. Also prints the
# machine, the revision and the time, since shared machines drift from hour to hour (bench/README.md): a table is a
# reading of one hour of one machine, and the range shows how much its minutes differed.
# Usage: scripts/bench_targets.sh [ROUNDS] [MIN_TIME]
#   ROUNDS: separate runs of the program (default 3); MIN_TIME: --benchmark_min_time (default 0.3).
#   BUILD_DIR (environment): the build to run (default build/; set up and built by scripts/setup.sh where it is not
#   there yet, else brought up to date).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-3}
min_time=${2:-0.3}
build=${BUILD_DIR:-build}
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "bench_targets: ROUNDS must be a whole number from 1, not '$rounds'" >&2; exit 2; }
[[ $min_time =~ ^[0-9]*\.?[0-9]+$ ]] || { echo "bench_targets: MIN_TIME must be seconds, not '$min_time'" >&2; exit 2; }
if [ -f "$build/CMakeCache.txt" ]; then cmake --build "$build" --target roomsense_bench >/dev/null
else ROOMSENSE_TARGET=roomsense_bench scripts/setup.sh "$build" >/dev/null; fi
bin="$build/bench/roomsense_bench"
# The cases behind the targets: thesis-room1's understanding and bounds (a bounds-only run, and the stage alone),
# the 20 x 14 m hall, the two-storey house, the 50 x 50 m floor (analyze_growth), the area search's heap on the
# largest floor (area_growth), and an added object's and a re-sent block's updates of thesis-room1 (78k vertices).
filter='^((understanding|bounds|analyze_bounds|analyze)/synthetic:(thesis-room1|hall|house)|analyze_growth/hall_50x50|area_growth/hall_90x90|update(_object)?/synthetic:thesis-room1/.*)$'

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((r = 1; r <= rounds; ++r)); do
  echo "run $r of $rounds" >&2
  "$bin" --benchmark_min_time="$min_time" --benchmark_filter="$filter" --benchmark_color=false 2>/dev/null |
    awk 'NF >= 5 && ($3 == "ns" || $3 == "us" || $3 == "ms" || $3 == "s")' > "$out/$r.txt"
done

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores; $(git rev-parse --short HEAD)$(git diff --quiet HEAD || echo ' + changes'); $(date -u '+%F %H:%M UTC')"
# Each line: name, real time, unit, CPU time, unit, iterations, then counters as key=value. Medians over the runs.
awk -v rounds="$rounds" '
  { name = $1; sub(/\/iterations:[0-9]+$/, "", name)
    k = ++n[name]; scale = $3 == "ns" ? 1e-6 : $3 == "us" ? 1e-3 : $3 == "s" ? 1e3 : 1
    v[name, "ms", k] = $2 * scale
    for (i = 7; i <= NF; ++i) { split($i, kv, "="); v[name, kv[1], k] = kv[2] + 0 } }
  # The values of a case over the runs into x[1..k], ascending; returns k.
  function sorted(name, key, x,   i, j, k, tmp) {
    k = 0
    for (i = 1; i <= n[name]; ++i) if ((name, key, i) in v) x[++k] = v[name, key, i]
    for (i = 2; i <= k; ++i) for (j = i; j > 1 && x[j - 1] > x[j]; --j) { tmp = x[j]; x[j] = x[j - 1]; x[j - 1] = tmp }
    return k
  }
  function median(name, key,   x, k) {
    k = sorted(name, key, x)
    if (k == 0) return -1
    return k % 2 ? x[(k + 1) / 2] : (x[k / 2] + x[k / 2 + 1]) / 2
  }
  # Lowest to highest of the runs, beside the median: the minutes of a shared VM differ.
  function range(name, key, format,   x, k) {
    k = sorted(name, key, x)
    return sprintf(format "-" format, x[1], x[k])
  }
  function row(target, name, key, limit, unit,   m) {
    m = median(name, key)
    if (m < 0) { printf "| %s | `%s` | not run | | |\n", target, name; return }
    printf "| %s | `%s`%s | %.3g %s | %s | %s |\n", target, name, key == "ms" ? "" : " " key, m, unit, range(name, key, "%.3g"),
           m <= limit ? "yes" : "no"
  }
  END {
    printf "| target (medians of %d runs) | case | measured | range of the runs | met |\n|---|---|---|---|---|\n", rounds
    row("understanding of thesis-room1 <= 5 ms", "understanding/synthetic:thesis-room1", "ms", 5, "ms")
    row("bounds of thesis-room1 <= 2 ms (a bounds-only run: StartRoomBounds)", "analyze_bounds/synthetic:thesis-room1", "ms", 2, "ms")
    row("(the bounds stage alone: I and its mesh)", "bounds/synthetic:thesis-room1", "ms", 2, "ms")
    row("the 20 x 14 m hall <= 25 ms", "understanding/synthetic:hall", "ms", 25, "ms")
    row("(the hall, understanding and bounds)", "analyze/synthetic:hall", "ms", 25, "ms")
    row("the two-storey house <= 30 ms", "analyze/synthetic:house", "ms", 30, "ms")
    row("the 50 x 50 m floor <= 1 s", "analyze_growth/hall_50x50", "ms", 1000, "ms")
    g = median("area_growth/hall_90x90", "grid_MB"); p = median("area_growth/hall_90x90", "peak_MB")
    if (g > 0) printf "| the area search within 4x the grid (90 x 90 m) | `area_growth/hall_90x90` | %.1f MB, %.2fx the grid (%.2f MB) | %s MB | %s |\n", p, p / g, g, range("area_growth/hall_90x90", "peak_MB", "%.1f"), p <= 4 * g ? "yes" : "no"
    row("an added 1,960-triangle object <= 1 ms, p50", "update_object/synthetic:thesis-room1", "p50_ms", 1, "ms")
    row("the same, p90", "update_object/synthetic:thesis-room1", "p90_ms", 1, "ms")
    row("a re-sent block (9,200 triangles) <= 1 ms, p50", "update/synthetic:thesis-room1", "p50_ms", 1, "ms")
    row("the same, p90", "update/synthetic:thesis-room1", "p90_ms", 1, "ms")
  }' "$out"/*.txt
