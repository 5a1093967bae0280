#!/usr/bin/env bash
# Regenerates docs/bench: the README's results tables and plots, from configs/bench/figure4.yaml,
# gap_sweep.yaml and narrow_passages.yaml (the Release build in build/, as tools/run.sh makes it,
# or $ACDPLAN_BUILD).
#   tools/bench.sh                    # all three, as many parallel runs as cores (~11 min on 2)
#   tools/bench.sh figure4 gap_sweep  # the README's table and plot only
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ACDPLAN_BUILD:-$root/build}
jobs=${ACDPLAN_BENCH_JOBS:-$(nproc)}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target acdplan -j "$jobs"
benches=("$@")
[[ ${#benches[@]} -eq 0 ]] && benches=(figure4 gap_sweep narrow_passages)
cd "$root"  # Paths in the outputs stay relative to the repository.
for bench in "${benches[@]}"; do
  /usr/bin/time -f "%e s wall" "$build/tools/acdplan" bench "configs/bench/$bench.yaml" \
    --jobs "$jobs" --out "docs/bench/$bench"
done
