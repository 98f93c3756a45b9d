#!/usr/bin/env bash
# Every test e2d has, from a fresh Debian 12 machine:
#   1. the release build: every library's GoogleTest suite, the benchmarks (short runs);
#   2. the same suites under AddressSanitizer + UndefinedBehaviorSanitizer, and the libraries
#      built as CMAKE_BUILD_TYPE=Release (-O3) with warnings as errors;
#   3. the libFuzzer targets, each for E2D_FUZZ_SECONDS (default 30), two at a time;
#   4. the consumer project, built against an install of e2d once per library, linking only it;
#   5. (first, it takes seconds) every C++ file follows .clang-format.
# Ends with one line "e2d tests: N passed, M failed". Exit status 0 only if all passed.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root="$PWD"
"$root/scripts/install-deps.sh" || exit 1

export MESA_SHADER_CACHE_DISABLE=true ALSOFT_DRIVERS=null
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
# Clones in other folders (CI's) reuse the cache: paths relative to the checkout, cwd not hashed.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
fuzz_seconds="${E2D_FUZZ_SECONDS:-30}"
logs="$root/build/logs"
mkdir -p "$logs"
passed=0
failed=0
failures=()
# Every stage header carries the time since the start, so a CI log shows where the time goes.
stage() { printf '=== [%d:%02d] %s\n' $((SECONDS / 60)) $((SECONDS % 60)) "$*"; }

# ctest_stage NAME PRESET: configure, build and test one configuration, counting its tests.
ctest_stage() {
  local name="$1" preset="$2"
  stage "$name: configure and build (preset $preset)"
  if ! cmake --preset "$preset" >"$logs/$preset-configure.log" 2>&1; then
    tail -30 "$logs/$preset-configure.log"
    failures+=("$name: configure failed (see $logs/$preset-configure.log)")
    failed=$((failed + 1))
    return
  fi
  if ! cmake --build --preset "$preset" >"$logs/$preset-build.log" 2>&1; then
    grep -E -A5 'error|FAILED' "$logs/$preset-build.log" | head -60
    failures+=("$name: build failed (see $logs/$preset-build.log)")
    failed=$((failed + 1))
    return
  fi
  stage "$name: test"
  ctest --preset "$preset" 2>&1 | tee "$logs/$preset-test.log" | grep -vE '^ +Start|Test +#[0-9]+: .* Passed'
  local line
  line=$(grep -E '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$logs/$preset-test.log" | tail -1)
  if [ -z "$line" ]; then
    failures+=("$name: ctest printed no summary")
    failed=$((failed + 1))
    return
  fi
  local nfail ntotal
  nfail=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
  ntotal=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\2/' <<<"$line")
  passed=$((passed + ntotal - nfail))
  failed=$((failed + nfail))
  [ "$nfail" -eq 0 ] || failures+=("$name: $nfail of $ntotal tests failed")
}

stage "format: every C++ file follows .clang-format"
if "$root/scripts/check-format.sh" 2>&1 | tee "$logs/format.log"; then
  passed=$((passed + 1))
else
  failures+=("format: see $logs/format.log")
  failed=$((failed + 1))
fi

ctest_stage "release" release
ctest_stage "asan+ubsan" asan

# A user's own optimised build of the libraries (CMAKE_BUILD_TYPE=Release, -O3, where GCC
# warns about things -O2 does not), warnings as errors; Debug and RelWithDebInfo are the two
# stages above.
stage "Release (-O3): the libraries as a user's dependency build makes them"
if cmake -S "$root" -B "$root/build/o3" -G Ninja -DCMAKE_BUILD_TYPE=Release -DE2D_WARNINGS_AS_ERRORS=ON \
     -DE2D_BUILD_TESTS=OFF -DE2D_BUILD_APPS=OFF -DE2D_BUILD_VALIDATION=OFF -DE2D_BUILD_BENCH=OFF \
     >"$logs/o3-configure.log" 2>&1 && cmake --build "$root/build/o3" >"$logs/o3-build.log" 2>&1; then
  echo "Release (-O3): every library builds without a warning"
  passed=$((passed + 1))
else
  grep -E -A5 'error|warning|FAILED' "$logs/o3-configure.log" "$logs/o3-build.log" | head -60
  failures+=("Release (-O3) build failed (see $logs/o3-build.log)")
  failed=$((failed + 1))
fi

stage "fuzz: libFuzzer targets, ${fuzz_seconds}s each"
if cmake --preset fuzz >"$logs/fuzz-configure.log" 2>&1 && cmake --build --preset fuzz >"$logs/fuzz-build.log" 2>&1; then
  # Every fuzzer: build/fuzz/<dir>/fuzz/fuzz_<name> for <dir> libs/<lib> or validation, seeds in
  # <dir>/fuzz/corpus/fuzz_<name>/ of the source tree (replayed every run). Two run at a time, one
  # per core; each writes its own log, read when both of its pair have finished.
  fuzzers=()
  for fuzzer in "$root"/build/fuzz/libs/*/fuzz/fuzz_* "$root"/build/fuzz/validation/fuzz/fuzz_*; do
    [ -f "$fuzzer" ] && [ -x "$fuzzer" ] && fuzzers+=("$fuzzer")
  done
  run_fuzzer() {
    local fuzzer="$1" target dir corpus
    local -a seeds
    target=$(basename "$fuzzer")
    dir=$(dirname "$(dirname "${fuzzer#"$root/build/fuzz/"}")")
    corpus="$root/build/fuzz/corpus/$target"
    mkdir -p "$corpus"
    seeds=()
    [ -d "$root/$dir/fuzz/corpus/$target" ] && seeds+=("$root/$dir/fuzz/corpus/$target")
    # The scenario reader's fuzzers also start from every shipped scenario.
    [ "$dir" = validation ] && seeds+=("$root/validation/scenarios")
    # A dictionary of the format's tokens, when the fuzzer has one (<dir>/fuzz/fuzz_<name>.dict).
    local -a dict=()
    [ -f "$root/$dir/fuzz/$target.dict" ] && dict=(-dict="$root/$dir/fuzz/$target.dict")
    "$fuzzer" -max_total_time="$fuzz_seconds" -print_final_stats=1 "${dict[@]}" \
      -artifact_prefix="$logs/$target-" "$corpus" "${seeds[@]}" >"$logs/$target.log" 2>&1
    echo $? >"$logs/$target.status"
  }
  fuzz_result() {
    local target
    target=$(basename "$1")
    if [ "$(cat "$logs/$target.status" 2>/dev/null)" = 0 ]; then
      echo "$target: ok ($(grep -E 'stat::number_of_executed_units' "$logs/$target.log" | awk '{print $2}') runs)"
      passed=$((passed + 1))
    else
      tail -40 "$logs/$target.log"
      failures+=("fuzz: $target found a failure (see $logs/$target.log)")
      failed=$((failed + 1))
    fi
  }
  for ((i = 0; i < ${#fuzzers[@]}; i += 2)); do
    run_fuzzer "${fuzzers[i]}" &
    if [ $((i + 1)) -lt ${#fuzzers[@]} ]; then run_fuzzer "${fuzzers[i + 1]}" & fi
    wait
    fuzz_result "${fuzzers[i]}"
    if [ $((i + 1)) -lt ${#fuzzers[@]} ]; then fuzz_result "${fuzzers[i + 1]}"; fi
  done
  if [ ${#fuzzers[@]} -eq 0 ]; then
    failures+=("fuzz: the fuzz build made no fuzzer")
    failed=$((failed + 1))
  fi
else
  tail -30 "$logs/fuzz-build.log" "$logs/fuzz-configure.log"
  failures+=("fuzz: build failed")
  failed=$((failed + 1))
fi

stage "consumer: find_package(e2d COMPONENTS <each library>) against an install"
if "$root/scripts/check-consumer.sh" "$root/build/release" 2>&1 | tee "$logs/consumer.log"; then
  passed=$((passed + 1))
else
  failures+=("consumer: see $logs/consumer.log")
  failed=$((failed + 1))
fi

for f in "${failures[@]}"; do echo "FAILED: $f"; done
stage "done"
echo "e2d tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
