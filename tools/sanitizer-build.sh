# Sourced by tools/test.sh --sanitize and tools/fuzz.sh: the one sanitizer build both use. A
# single tree ($ACDPLAN_ASAN_BUILD_DIR, default build-asan/) holds the ASan+UBSan test suite and
# the libFuzzer targets, compiled once with clang (coverage instrumentation included), so the
# configure arguments must be the same from both scripts or each would rebuild the tree.
# Each script adds -DACDPLAN_WARNINGS_AS_ERRORS from $ACDPLAN_WERROR.
sanitizer_build_dir=${ACDPLAN_ASAN_BUILD_DIR:-build-asan}
sanitizer_cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++
  -DACDPLAN_SANITIZE=ON -DACDPLAN_FUZZ=ON -DACDPLAN_TSAN=OFF -DACDPLAN_BUILD_TESTS=ON
  -DACDPLAN_BUILD_TOOLS=ON)
