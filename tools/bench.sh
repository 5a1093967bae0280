#!/usr/bin/env bash
# Regenerates docs/bench: the README's results tables and plots, from configs/bench/figure4.yaml
# and configs/bench/narrow_passages.yaml (a Release build in build-release, or $ACDPLAN_BUILD).
#   tools/bench.sh            # both benchmarks, as many parallel runs as cores
#   tools/bench.sh figure4    # only one of them
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ACDPLAN_BUILD:-$root/build-release}
jobs=${ACDPLAN_BENCH_JOBS:-$(nproc)}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target acdplan -j "$jobs"
benches=("$@")
[[ ${#benches[@]} -eq 0 ]] && benches=(figure4 narrow_passages)
cd "$root"  # Paths in the outputs stay relative to the repository.
for bench in "${benches[@]}"; do
  /usr/bin/time -f "%e s wall" "$build/tools/acdplan" bench "configs/bench/$bench.yaml" \
    --jobs "$jobs" --out "docs/bench/$bench"
done
