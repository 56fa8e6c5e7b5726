#!/usr/bin/env bash
# Times this tree's roomsense_bench against another revision's, in runs whose order alternates (A B, B A, ...),
# and prints each case's median time (and, for update cases, median p50/p90) for both with their ratio. Shared
# machines drift: compare figures measured side by side like this, not against a table from another day. Two
# builds of the same code read 0.8-1.2 apart on this project's shared 2-core VM; for effects that small count
# instructions instead (valgrind --tool=callgrind), which repeat exactly.
# Usage: scripts/bench_compare.sh REV [FILTER] [ROUNDS] [MIN_TIME]
#   REV: a git revision (built once in build-compare/SHA, SHA's first 12 digits: a worktree of this repository)
#   FILTER: a --benchmark_filter regex (default '^(understanding|bounds_pipeline)/synthetic'); ROUNDS: runs of
#   each binary (default 3); MIN_TIME: --benchmark_min_time (default 0.2). This tree is built in build/ first.
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:?usage: scripts/bench_compare.sh REV [FILTER] [ROUNDS] [MIN_TIME]}
filter=${2:-'^(understanding|bounds_pipeline)/synthetic'}
rounds=${3:-3}
min_time=${4:-0.2}
sha=$(git rev-parse --verify "$rev^{commit}")
root=$PWD
other="$root/build-compare/${sha:0:12}"

if [ ! -x "$other/build/bench/roomsense_bench" ]; then
  mkdir -p "$root/build-compare"
  # The bench reads ../shared/rooms beside its own source tree.
  [ -e "$root/../shared" ] && ln -sfn "$root/../shared" "$root/build-compare/shared"
  [ -d "$other" ] || git worktree add --detach "$other" "$sha" >/dev/null
  cmake -S "$other" -B "$other/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$other/build" --target roomsense_bench
fi
cmake --build build --target roomsense_bench

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((r = 1; r <= rounds; ++r)); do
  order="base head"
  ((r % 2 == 0)) && order="head base"
  for which in $order; do
    bin=build/bench/roomsense_bench
    [ "$which" = base ] && bin="$other/build/bench/roomsense_bench"
    echo "round $r: $which" >&2
    # The console format: CSV needs every case to have the same counters.
    "$bin" --benchmark_min_time="$min_time" --benchmark_filter="$filter" --benchmark_color=false 2>/dev/null |
      awk 'NF >= 5 && ($3 == "ns" || $3 == "us" || $3 == "ms" || $3 == "s")' > "$out/$which.$r.txt"
  done
done

# Each line: name, real time, unit, CPU time, unit, iterations, then counters as key=value. Medians over the rounds.
awk -v rounds="$rounds" '
  FNR == 1 { np = split(FILENAME, part, "/"); which = substr(part[np], 1, 4) }
  { name = $1; if (!(name in seen)) { seen[name] = 1; order[++cases] = name }
    k = ++n[which, name]; t[which, name, k] = $2; unit[name] = $3
    for (i = 7; i <= NF; ++i) {
      split($i, kv, "=")
      if (kv[1] == "p50_ms") p50[which, name, k] = kv[2] + 0
      if (kv[1] == "p90_ms") p90[which, name, k] = kv[2] + 0
    } }
  function median(arr, which, name, count,   v, i, j, k, tmp) {
    k = 0
    for (i = 1; i <= count; ++i) if ((which, name, i) in arr) v[++k] = arr[which, name, i] + 0
    if (k == 0) return ""
    for (i = 2; i <= k; ++i) for (j = i; j > 1 && v[j - 1] > v[j]; --j) { tmp = v[j]; v[j] = v[j - 1]; v[j - 1] = tmp }
    return k % 2 ? v[(k + 1) / 2] : (v[k / 2] + v[k / 2 + 1]) / 2
  }
  function row(label, b, h, u) {
    if (b == "" || h == "") printf "%-64s %12s %12s\n", label, b == "" ? "-" : b u, h == "" ? "-" : h u
    else printf "%-64s %10.3f%-2s %10.3f%-2s %7.3f\n", label, b, u, h, u, h / b
  }
  END {
    printf "%-64s %12s %12s %7s\n", "case (medians of " rounds " runs each)", "base", "head", "head/base"
    for (c = 1; c <= cases; ++c) {
      name = order[c]
      row(name, median(t, "base", name, n["base", name]), median(t, "head", name, n["head", name]), unit[name])
      pb = median(p50, "base", name, n["base", name]); ph = median(p50, "head", name, n["head", name])
      if (pb != "" || ph != "") row("  p50", pb, ph, "ms")
      pb = median(p90, "base", name, n["base", name]); ph = median(p90, "head", name, n["head", name])
      if (pb != "" || ph != "") row("  p90", pb, ph, "ms")
    }
  }' "$out"/base.*.txt "$out"/head.*.txt
