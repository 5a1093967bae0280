#pragma once
// The message of the acdplan::InputError a call throws: how the tests check documented errors.

#include <string>

#include "base/input_error.h"

namespace acdplan::test {

/// The acdplan::InputError message `f()` throws, or "" when it throws nothing (any other
/// exception propagates, so the test fails on it).
template <typename F>
std::string InputErrorOf(F&& f) {
  try {
    f();
  } catch (const acdplan::InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace acdplan::test
