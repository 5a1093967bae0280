#!/usr/bin/env bash
# Builds acdplan and runs its whole test suite.
#
#   tools/test.sh             Release build in build/ (or $ACDPLAN_BUILD_DIR)
#   tools/test.sh --sanitize  ASan+UBSan RelWithDebInfo build in build-asan/
#                             (or $ACDPLAN_ASAN_BUILD_DIR); it builds the fuzz targets too,
#                             which tools/fuzz.sh then runs from the same tree
#   tools/test.sh --tsan      ThreadSanitizer RelWithDebInfo build in build-tsan/
#                             (or $ACDPLAN_TSAN_BUILD_DIR); builds and runs only the tests
#                             labelled `threads` (suppressions: tools/tsan.supp)
#
# The Release build uses the default compiler (GCC on Debian); the sanitizer builds use clang,
# which compiles the CGAL-heavy units with instrumentation in less than half of GCC's time
# (acd/internal/solid_acd.cpp with ASan+UBSan: 18 s of CPU against 45 s); so the code is also
# checked by a second compiler's warnings.
#
# Ends with one line "acdplan tests: N passed, M failed"; exits 0 only if every test passed.
# $ACDPLAN_JOBS overrides the parallelism (default: nproc); ACDPLAN_WERROR=1 makes compiler
# warnings errors (.ci/run sets it).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

sanitize=0
tsan=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=1 ;;
    --tsan) tsan=1 ;;
    -h|--help) sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "test.sh: unknown argument '$arg' (expected --sanitize or --tsan)" >&2; exit 2 ;;
  esac
done
if [[ $sanitize -eq 1 && $tsan -eq 1 ]]; then
  echo "test.sh: --sanitize and --tsan are exclusive (ThreadSanitizer cannot run with ASan)" >&2
  exit 2
fi

jobs=${ACDPLAN_JOBS:-$(nproc)}
# ccache (CMakeLists.txt uses it when installed) shares its objects between checkouts: paths
# relative to this one, and the debug-info builds' working folder left out of the hash. Its
# depend mode keys an object by the headers the compiler's own dependency file lists (CMake
# passes -MD), so a miss does not first run the preprocessor to look for it: that run cost
# 1.6 s (clang) to 4.3 s (GCC) of CPU on acd's largest unit, on every miss of a cold build.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
export CCACHE_DEPEND=${CCACHE_DEPEND:-1}
# Given on every configure, so a tree first configured with another compiler is reconfigured.
clang_args=(-DCMAKE_CXX_COMPILER=clang++)
label="acdplan tests"
build_targets=()
ctest_args=()

if [[ $sanitize -eq 1 ]]; then
  build_dir=${ACDPLAN_ASAN_BUILD_DIR:-build-asan}
  cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DACDPLAN_SANITIZE=ON -DACDPLAN_FUZZ=ON
    -DACDPLAN_UNITY_UNITS=ON "${clang_args[@]}")
  # Options already in the environment come last, so they win.
  export ASAN_OPTIONS="detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
  echo "test.sh: sanitizer build in $build_dir (ASan + UBSan)"
elif [[ $tsan -eq 1 ]]; then
  build_dir=${ACDPLAN_TSAN_BUILD_DIR:-build-tsan}
  # Its library files compile one by one, not in units (cmake/AcdplanUnity.cmake): so each is
  # still checked to compile on its own.
  cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DACDPLAN_SANITIZE=OFF -DACDPLAN_TSAN=ON
    -DACDPLAN_BUILD_TOOLS=OFF -DACDPLAN_UNITY_UNITS=OFF "${clang_args[@]}")
  # Only the test executables of the `threads` label (tests/*/CMakeLists.txt), so the step
  # stays short; halt_on_error makes the first race fail its test.
  build_targets=(--target planning_parallel_test)
  ctest_args=(-L threads)
  label="acdplan threads tests (TSan)"
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tools/tsan.supp${TSAN_OPTIONS:+:$TSAN_OPTIONS}"
  echo "test.sh: ThreadSanitizer build in $build_dir (tests labelled 'threads' only)"
else
  build_dir=${ACDPLAN_BUILD_DIR:-build}
  cmake_args=(-DCMAKE_BUILD_TYPE=Release -DACDPLAN_SANITIZE=OFF -DACDPLAN_UNITY_UNITS=ON)
fi

"$root/tools/install-deps.sh"

if [[ ${ACDPLAN_WERROR:-0} == 1 ]]; then
  cmake_args+=(-DACDPLAN_WARNINGS_AS_ERRORS=ON)
else
  cmake_args+=(-DACDPLAN_WARNINGS_AS_ERRORS=OFF)
fi

# Each test executable runs as a few gtest shards, not one process per test
# (tests/CMakeLists.txt): the per-process start-up was a quarter of the Release suite's CPU time.
if ! cmake -S "$root" -B "$build_dir" "${cmake_args[@]}" -DACDPLAN_BUILD_TESTS=ON \
  -DACDPLAN_TEST_SHARDS=ON; then
  echo "$label: 0 passed, 0 failed (configure failed, no tests ran)"
  exit 1
fi
if ! cmake --build "$build_dir" -j "$jobs" "${build_targets[@]}"; then
  echo "$label: 0 passed, 0 failed (build failed, no tests ran)"
  exit 1
fi

log="$build_dir/ctest-summary.log"
# The gtest shards write their gtest XML here (tests/CMakeLists.txt); results of an earlier run
# must not be counted.
xml_dir="$build_dir/gtest-xml"
rm -rf "$xml_dir"
set +e
(cd "$build_dir" && ctest --output-on-failure --no-tests=error -j "$jobs" "${ctest_args[@]}") 2>&1 | tee "$log"
ctest_status=${PIPESTATUS[0]}
set -e

# ctest's summary: "97% tests passed, 1 tests failed out of 34".
summary=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1 || true)
if [[ -z "$summary" ]]; then
  echo "$label: 0 passed, 0 failed (ctest found no tests or did not finish; status $ctest_status)"
  exit 1
fi
failed=$(sed -E 's/^[0-9]+% tests passed, ([0-9]+) tests? failed.*/\1/' <<<"$summary")
total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$summary")
passed=$((total - failed))
if [[ -d $xml_dir ]]; then
  # Count test cases, not shards: every shard's XML root is
  # <testsuites tests="N" failures="F" disabled="D" errors="E" ...>; the other ctest entries
  # (the find_package consumers) count one each. A shard that failed without writing its XML
  # (a crash) counts as one failure.
  read -r cases case_failed < <(cat "$xml_dir"/*.xml 2>/dev/null |
    sed -nE 's/.*<testsuites tests="([0-9]+)" failures="([0-9]+)" disabled="[0-9]+" errors="([0-9]+)".*/\1 \2 \3/p' |
    awk '{t += $1; f += $2 + $3} END {print t + 0, f + 0}')
  results=$(grep -E '^ *[0-9]+/[0-9]+ Test +#[0-9]+: ' "$log" || true)
  shards=$(grep -c '\.shard' <<<"$results" || true)
  shards_failed=$(grep '\.shard' <<<"$results" | grep -vc ' Passed ' || true)
  others_passed=$(grep -v '\.shard' <<<"$results" | grep -c ' Passed ' || true)
  others_failed=$(grep -v '\.shard' <<<"$results" | grep -vc ' Passed ' || true)
  [[ $case_failed -eq 0 ]] && case_failed=$shards_failed
  passed=$((cases - case_failed + others_passed))
  failed=$((case_failed + others_failed))
  label="$label ($shards gtest shards)"
fi
echo "$label: $passed passed, $failed failed"
if [[ $failed -ne 0 || $ctest_status -ne 0 ]]; then
  exit 1
fi
exit 0
