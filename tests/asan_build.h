// ACDPLAN_ASAN_BUILD: 1 when this test is built with AddressSanitizer (tools/test.sh
// --sanitize), else 0. The code runs 10-20x slower there, so the heavy sweeps check a
// representative subset. GCC defines __SANITIZE_ADDRESS__; clang answers
// __has_feature(address_sanitizer) instead.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define ACDPLAN_ASAN_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ACDPLAN_ASAN_BUILD 1
#endif
#endif
#ifndef ACDPLAN_ASAN_BUILD
#define ACDPLAN_ASAN_BUILD 0
#endif

namespace acdplan::test {

/// Seeds (or runs) of the success-rate tests, which plan once per seed and count the solved
/// ones: 10 in a normal build; under ASan, where the 3D plans run 15-30x slower, the first 4:
/// the same code on fewer runs for the sanitizers, the rates themselves checked in Release.
constexpr int kRateSeeds = ACDPLAN_ASAN_BUILD ? 4 : 10;

}  // namespace acdplan::test
