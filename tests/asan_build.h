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
