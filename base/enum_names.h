#pragma once
// Enums as names: each enum of the project has one table of (value, name) pairs, and its
// ToString() / Parse<Enum>() pair is written with these two functions over that table, so
// every name is spelled once and every parse error reads the same.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "base/input_error.h"

namespace acdplan {

template <typename Enum>
struct EnumName {
  Enum value;
  const char* name;
};

/// The name of `value` in `table` ("unknown" for a value not in it).
template <typename Enum, std::size_t N>
std::string NameOf(const std::array<EnumName<Enum>, N>& table, Enum value) {
  for (const EnumName<Enum>& entry : table) {
    if (entry.value == value) return entry.name;
  }
  return "unknown";
}

/// Every name of `table`, in its order.
template <typename Enum, std::size_t N>
std::vector<std::string> NamesOf(const std::array<EnumName<Enum>, N>& table) {
  std::vector<std::string> names;
  for (const EnumName<Enum>& entry : table) names.push_back(entry.name);
  return names;
}

/// The value named `name` in `table`.
/// @throws InputError "unknown <what> '<name>' (expected one of: ...)" otherwise.
template <typename Enum, std::size_t N>
Enum ValueOf(const std::array<EnumName<Enum>, N>& table, const std::string& name,
             const std::string& what) {
  for (const EnumName<Enum>& entry : table) {
    if (name == entry.name) return entry.value;
  }
  throw InputError(UnknownName(what, name, NamesOf(table)));
}

}  // namespace acdplan
