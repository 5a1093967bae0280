#!/usr/bin/env bash
# Builds acdplan (Release, in build/ or $ACDPLAN_BUILD_DIR) and runs the main job: the
# approximate convex decomposition of the Nazca monkey (dissertation Ch. IV), written as JSON
# and SVG under out/demo/.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

shared="$(cd "$root/.." && pwd)/shared"
input="$shared/data/polygons/acd2d/nazca/nazca_monkey.poly"
if [[ ! -f "$input" ]]; then
  echo "run.sh: input polygon not found: $input" >&2
  echo "run.sh: the shared data folder must sit next to the repository (../shared/data)." >&2
  exit 2
fi

build_dir=${ACDPLAN_BUILD_DIR:-build}
jobs=${ACDPLAN_JOBS:-$(nproc)}

"$root/tools/install-deps.sh"
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DACDPLAN_SANITIZE=OFF >/dev/null
if ! cmake --build "$build_dir" -j "$jobs" --target acdplan; then
  echo "run.sh: building the acdplan command (target 'acdplan') failed" >&2
  exit 1
fi

out="$root/out/demo"
mkdir -p "$out"
status=0
"$build_dir/tools/acdplan" decompose "$input" --tau-rel 0.01 \
  --json "$out/decomposition.json" --svg "$out/decomposition.svg" || status=$?
if [[ $status -ne 0 ]]; then
  echo "run.sh: acdplan decompose failed with exit status $status" >&2
  exit "$status"
fi

echo "acdplan run: decomposition of $(basename "$input") written to"
echo "  $out/decomposition.json"
echo "  $out/decomposition.svg"
