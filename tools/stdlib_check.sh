#!/usr/bin/env bash
# Checks that the decompositions do not depend on the C++ standard library: builds
# acd_fingerprint with clang and libc++ in build-libcxx/ (or $ACDPLAN_LIBCXX_BUILD_DIR), with
# CGAL's own GMP wrappers (GMP's C++ classes are built for libstdc++), and compares its
# fingerprints (the hash of each whole decomposition) with those of the Release build
# (tools/test.sh, in build/ or $ACDPLAN_BUILD_DIR: GCC, libstdc++, gmpxx): every polygon under
# data/polygons (four measures, three tolerances) and the meshes of data/meshes/vhacd (tau_rel
# 0.05) but the four whose repair and ACD take seconds each.
#
# Where the two differ, something was left to the library (a sort or heap with ties, a hash
# container's iteration) or to the exact number type (how a rational is rounded): the differing
# lines are printed.
#
# Ends with one line "acdplan libc++ results: N passed, M failed" (a line per file, measure and
# tolerance); exits 0 only if all are the same.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

case "${1:-}" in
  "") ;;
  -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "stdlib_check.sh: no arguments expected, got '$1'" >&2; exit 2 ;;
esac

label="acdplan libc++ results"
reference_build=${ACDPLAN_BUILD_DIR:-build}
reference="$reference_build/tools/acd_fingerprint"
if [[ ! -x $reference ]]; then
  echo "stdlib_check.sh: $reference is missing: run tools/test.sh first" >&2
  echo "$label: 0 passed, 0 failed (no reference build)"
  exit 1
fi
build_dir=${ACDPLAN_LIBCXX_BUILD_DIR:-build-libcxx}
jobs=${ACDPLAN_JOBS:-$(nproc)}
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
export CCACHE_DEPEND=${CCACHE_DEPEND:-1}

"$root/tools/install-deps.sh"

werror=OFF
[[ ${ACDPLAN_WERROR:-0} == 1 ]] && werror=ON
# GMP's C++ classes are built against libstdc++: CGAL's own wrappers of GMP instead.
if ! cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS=-stdlib=libc++ -DCGAL_WITH_GMPXX=OFF -DACDPLAN_SANITIZE=OFF \
  -DACDPLAN_UNITY_UNITS=ON -DACDPLAN_BUILD_TESTS=OFF -DACDPLAN_WARNINGS_AS_ERRORS=$werror ||
  ! cmake --build "$build_dir" -j "$jobs" --target acd_fingerprint; then
  echo "$label: 0 passed, 0 failed (the libc++ build failed)"
  exit 1
fi

meshes=()
for mesh in data/meshes/vhacd/*.obj; do
  case "$(basename "$mesh")" in
    mite.obj | al.obj | teddy.obj | cow-nonormals.obj) ;;  # 2 - 50 s each.
    *) meshes+=("$mesh") ;;
  esac
done
fingerprints() {
  "$1" --measure sl --measure h2 --measure sp --measure h1 \
    --tau-rel 0 --tau-rel 0.01 --tau-rel 0.05 data/polygons | grep -v '^all '
  "$1" --tau-rel 0.05 "${meshes[@]}" | grep -v '^all '
}
expected=$(fingerprints "$reference")
actual=$(fingerprints "$build_dir/tools/acd_fingerprint")
total=$(wc -l <<<"$expected")
differing=$(diff <(echo "$expected") <(echo "$actual") | grep -c '^<' || true)
if [[ $differing -ne 0 ]]; then
  echo "stdlib_check.sh: libstdc++ (<) and libc++ (>) decompose differently:"
  diff <(echo "$expected") <(echo "$actual") || true
fi
echo "$label: $((total - differing)) passed, $differing failed"
[[ $differing -eq 0 ]]
