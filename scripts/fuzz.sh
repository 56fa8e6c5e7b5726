#!/usr/bin/env bash
# Fuzzing (README, "Fuzzing and ThreadSanitizer"): builds the libFuzzer harnesses of fuzz/ with clang, ASan and
# UBSan, generates the seed corpora from the synthetic rooms, and runs every harness for SECONDS, two at a time
# (each is single-threaded). Fails when any harness finds a crash, a leak, a timeout or an out-of-memory, and
# prints the reproducer: replay it with BUILD_DIR/fuzz/fuzz_NAME FILE, minimize it with
# BUILD_DIR/fuzz/fuzz_NAME -minimize_crash=1 -runs=10000 FILE, and keep the minimized input as a regression
# test in tests/fuzz_regressions/NAME/ (the ctest fuzz.replay.NAME replays that folder in every build).
# Usage: scripts/fuzz.sh [BUILD_DIR] [SECONDS] [extra cmake arguments...]
#   BUILD_DIR defaults to build-fuzz, SECONDS (per harness) to 60; 0 only builds and writes the seeds.
#   ROOMSENSE_FUZZERS="analyze obj" runs only those; ROOMSENSE_FUZZ_JOBS (default 2) harnesses run at once;
#   ROOMSENSE_FUZZ_TIMEOUT (default 20) seconds for one input before it counts as a hang.
# The corpora grow in BUILD_DIR/fuzz-corpus/NAME and are kept between runs; findings go to
# BUILD_DIR/fuzz-artifacts/NAME/, logs to BUILD_DIR/fuzz-logs/NAME.log.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-fuzz}
seconds=${2:-60}
shift 2 || shift $# || true
harnesses=(${ROOMSENSE_FUZZERS:-analyze quest_capture capi_thesis capi_handle obj ply})
jobs=${ROOMSENSE_FUZZ_JOBS:-2}
timeout=${ROOMSENSE_FUZZ_TIMEOUT:-20}

# Only the harnesses and the seed generator are built, with coverage feedback from all the code they link.
# clang and its fuzzer runtime (libclang_rt.fuzzer lives in libclang-rt-14-dev on Debian 12) come with the rest.
ROOMSENSE_EXTRA_PACKAGES="clang libclang-rt-14-dev" \
  CC=clang CXX=clang++ ROOMSENSE_BUILD_TYPE=RelWithDebInfo ROOMSENSE_UNITY=1 ROOMSENSE_TARGET=roomsense_fuzzers \
  scripts/setup.sh "$build_dir" -DROOMSENSE_BUILD_FUZZERS=ON -DROOMSENSE_SANITIZE=address,undefined \
  -DROOMSENSE_BUILD_TESTS=OFF -DROOMSENSE_BUILD_BENCH=OFF -DROOMSENSE_WITH_VULKAN=OFF "$@"

bin="$(cd "$build_dir" && pwd)/fuzz"  # BUILD_DIR relative or absolute
"$bin/roomsense_fuzz_seeds" "$build_dir/fuzz-seeds" >/dev/null
((seconds > 0)) || exit 0
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}

run_one() {  # harness: the corpus starts from the seeds and the regression inputs; libFuzzer's exit status
  local h=$1 corpus="$build_dir/fuzz-corpus/$1" artifacts="$build_dir/fuzz-artifacts/$1/"
  mkdir -p "$corpus" "$artifacts"
  cp -n "$build_dir/fuzz-seeds/$h"/* "$corpus"/ 2>/dev/null || true
  [ -d "tests/fuzz_regressions/$h" ] && cp -n "tests/fuzz_regressions/$h"/* "$corpus"/ 2>/dev/null || true
  local dict=()
  case $h in
    obj) dict=(-dict=fuzz/obj.dict) ;;
    ply) dict=(-dict=fuzz/ply.dict) ;;
    quest_capture) dict=(-dict=fuzz/quest_capture.dict) ;;
  esac
  "$bin/fuzz_$h" "${dict[@]}" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
    -artifact_prefix="$artifacts" -print_final_stats=1 "$corpus" >"$build_dir/fuzz-logs/$h.log" 2>&1
}

mkdir -p "$build_dir/fuzz-logs"
declare -A pid_of
for h in "${harnesses[@]}"; do
  [ -x "$bin/fuzz_$h" ] || { echo "fuzz: no harness fuzz_$h in $bin" >&2; exit 2; }
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  echo "== fuzz_$h for ${seconds} s"
  run_one "$h" &
  pid_of[$h]=$!
done

failed=0
printf '%-14s %10s %8s %7s %7s %8s  %s\n' harness runs exec/s cov ft corpus result
for h in "${harnesses[@]}"; do
  status=0
  wait "${pid_of[$h]}" || status=$?
  log="$build_dir/fuzz-logs/$h.log"
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+.*cov: ' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9]*[a-zA-Z]*\).*/\1/p' <<<"$last")
  result=ok
  if ((status != 0)); then
    failed=1
    result="FAILED (exit $status)"
  fi
  printf '%-14s %10s %8s %7s %7s %8s  %s\n' "$h" "${runs:-?}" "${speed:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$result"
done
if ((failed)); then
  for h in "${harnesses[@]}"; do
    log="$build_dir/fuzz-logs/$h.log"
    grep -qE '^(==[0-9]+==ERROR|SUMMARY|.*Test unit written to)' "$log" || grep -q 'ERROR: libFuzzer' "$log" || continue
    echo "== fuzz_$h: finding (log $log)"
    grep -E 'ERROR: (AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error:|invariant broken|contract broken|SUMMARY:' "$log" | head -5
    sed -n 's/.*Test unit written to \(.*\)/reproducer: \1/p' "$log"
    echo "replay: $bin/fuzz_$h FILE; minimize: $bin/fuzz_$h -minimize_crash=1 -runs=10000 FILE"
  done
  exit 1
fi
