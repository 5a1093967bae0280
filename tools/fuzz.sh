#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, one per reader) in the sanitizer tree, build-asan/ (or
# $ACDPLAN_ASAN_BUILD_DIR; clang, ASan + UBSan, configured as `tools/test.sh --sanitize` does,
# which builds them too), and runs them, $ACDPLAN_JOBS (default: nproc) at a time, the slowest
# first; each target is one single-threaded process.
#
#   tools/fuzz.sh [SECONDS] [TARGET...]   SECONDS per target (default 20); TARGET e.g.
#                                         poly_reader or fuzz_poly_reader (default: all)
#   tools/fuzz.sh --list                  the target names
#
# Each target runs on its working corpus, <build>/fuzz-corpus/<target>/: the seeds of
# fuzz/corpus/<target>/ copied in (the repository is never written), plus what earlier runs
# found. Options: -max_total_time=SECONDS -timeout=10 -rss_limit_mb=2048. A crash, sanitizer
# report, leak, time-out or out-of-memory leaves a reproducer in <build>/fuzz-artifacts/<target>/
# and its path is printed; replay it with `<build>/fuzz/fuzz_<target> <reproducer>`.
# Logs: <build>/fuzz-logs/<target>.log. Exits 0 only if no target found anything.
# $ACDPLAN_JOBS sets the build's and the runs' parallelism (default: nproc); ACDPLAN_WERROR=1
# makes compiler warnings errors (.ci/run sets it); ACDPLAN_FUZZ_RUNS=N runs N inputs per target
# from seed 1 instead of SECONDS (reproducible; .ci/run sets it).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

seconds=20
if [[ $# -gt 0 && "$1" =~ ^[0-9]+$ ]]; then
  seconds=$1
  shift
fi
list=0
requested=()
for arg in "$@"; do
  case "$arg" in
    -h|--help) sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --list) list=1 ;;
    -*) echo "fuzz.sh: unknown option '$arg' (expected SECONDS, targets, --list or --help)" >&2
      exit 2 ;;
    *) requested+=("${arg#fuzz_}") ;;
  esac
done
if [[ $seconds -lt 1 ]]; then
  echo "fuzz.sh: SECONDS must be at least 1, got $seconds" >&2
  exit 2
fi

mapfile -t all < <(cd fuzz && ls fuzz_*.cpp | sed -e 's/^fuzz_//' -e 's/\.cpp$//' | grep -vx input)
if [[ $list -eq 1 ]]; then
  printf '%s\n' "${all[@]}"
  exit 0
fi
targets=("${requested[@]:-${all[@]}}")
for t in "${targets[@]}"; do
  if [[ ! -f "fuzz/fuzz_$t.cpp" ]]; then
    echo "fuzz.sh: unknown target '$t' (expected one of: ${all[*]})" >&2
    exit 2
  fi
done

if ! command -v clang++ >/dev/null 2>&1; then
  echo "fuzz.sh: clang++ not found (tools/install-deps.sh installs clang)" >&2
  exit 1
fi

build_dir=${ACDPLAN_ASAN_BUILD_DIR:-build-asan}
jobs=${ACDPLAN_JOBS:-$(nproc)}
werror=OFF
if [[ ${ACDPLAN_WERROR:-0} == 1 ]]; then werror=ON; fi

start=$SECONDS
# The options of `tools/test.sh --sanitize`, so that the two share one tree without
# reconfiguring it.
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DACDPLAN_SANITIZE=ON \
  -DACDPLAN_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DACDPLAN_WARNINGS_AS_ERRORS=$werror >/dev/null
if ! cmake --build "$build_dir" -j "$jobs" --target acdplan_fuzz; then
  echo "fuzz.sh: building the fuzz targets failed" >&2
  exit 1
fi
echo "fuzz.sh: built ${#all[@]} targets in $((SECONDS - start)) s"

# Leaks are findings too; UBSan already aborts (-fno-sanitize-recover), print its stack.
export ASAN_OPTIONS="detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"

# $ACDPLAN_FUZZ_RUNS: that many inputs per target from seed 1 (reproducible, for CI) instead
# of SECONDS of fuzzing. A seed alone does not make a run repeat: libFuzzer rereads the corpus
# folder every second (re-running the seeds it did not keep, at times the clock decides), and
# turns the operands of comparisons into bytes to insert, some of them stack addresses; both
# are off here. Where ASLR can be turned off for the runs, it is: code that orders or hashes
# heap addresses (yaml-cpp's node memory, CGAL's constraint sets) takes other branches when the
# allocator's regions move, and those branches are coverage. Checked: all 13 targets try the same
# inputs in the same order run after run, and the scenario reader whatever the environment's size,
# stack limit or corpus path. A checkout at another path is another build (the sanitizers embed
# each file's absolute path, which moves the code and data): 5 targets then try other inputs.
launch=()
if [[ -n ${ACDPLAN_FUZZ_RUNS:-} ]]; then
  budget=(-runs="$ACDPLAN_FUZZ_RUNS" -seed=1 -reload=0 -use_cmp=0)
  if setarch "$(uname -m)" -R true 2>/dev/null; then
    launch=(setarch "$(uname -m)" -R)
  else
    echo "fuzz.sh: cannot turn ASLR off here (setarch -R); runs may differ from other machines'"
  fi
else
  budget=(-max_total_time="$seconds")
fi

# One target's run; its one-line result goes to <build>/fuzz-logs/<target>.result, so the results
# print in the targets' order whatever order the runs end in.
run_target() {
  local t=$1
  local corpus="$build_dir/fuzz-corpus/$t"
  local artifacts="$build_dir/fuzz-artifacts/$t"
  local log="$build_dir/fuzz-logs/$t.log"
  local result="$build_dir/fuzz-logs/$t.result"
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  if [[ -d "fuzz/corpus/$t" ]]; then
    cp -n fuzz/corpus/"$t"/* "$corpus"/ 2>/dev/null || true
  fi
  rm -f "$artifacts"/* "$result"
  local t0=$SECONDS status
  set +e
  "${launch[@]}" "$build_dir/fuzz/fuzz_$t" "${budget[@]}" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" >"$log" 2>&1
  status=$?
  set -e
  local runs found
  runs=$(grep -E '^stat::number_of_executed_units:' "$log" | awk '{print $2}' | tail -n 1)
  mapfile -t found < <(find "$artifacts" -type f | sort)
  if [[ $status -ne 0 || ${#found[@]} -gt 0 ]]; then
    {
      echo "fuzz.sh: $t: FOUND A PROBLEM after $((SECONDS - t0)) s (status $status); log: $log"
      grep -E 'ERROR: |SUMMARY: |runtime error|CheckDecomposition failed|terminate called|what\(\)' \
        "$log" | head -n 8 || true
      for f in "${found[@]}"; do echo "fuzz.sh: $t: reproducer: $f"; done
    } >"$result"
  else
    echo "fuzz.sh: $t: ok, ${runs:-?} inputs in $((SECONDS - t0)) s, corpus $(ls "$corpus" | wc -l) files" >"$result"
  fi
}

# The slowest targets start first, so that no core idles at the end waiting on one of them
# (CI's 3,000 inputs on a 2-core VM: decompose3d 42 s, ompl_app_problem 34 s, bench_yaml 10 s,
# the other ten 1 - 5 s each).
slowest=(decompose3d ompl_app_problem bench_yaml)
order=()
for t in "${slowest[@]}" "${targets[@]}"; do
  if [[ " ${targets[*]} " == *" $t "* && " ${order[*]} " != *" $t "* ]]; then order+=("$t"); fi
done
running=0
for t in "${order[@]}"; do
  if [[ $running -ge $jobs ]]; then
    wait -n || true
    running=$((running - 1))
  fi
  run_target "$t" &
  running=$((running + 1))
done
wait

failed=()
for t in "${targets[@]}"; do
  result="$build_dir/fuzz-logs/$t.result"
  if [[ ! -f $result ]]; then
    echo "fuzz.sh: $t: no result (its run did not finish)" >&2
    failed+=("$t")
  elif grep -q 'FOUND A PROBLEM' "$result"; then
    cat "$result" >&2
    failed+=("$t")
  else
    cat "$result"
  fi
done

if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz.sh: ${#failed[@]} of ${#targets[@]} targets found problems: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz.sh: ${#targets[@]} targets (${budget[*]} each), nothing found"
