#pragma once
// Counting a substring: how the writer tests check what a text holds.

#include <string>

namespace acdplan::test {

/// How many times `what` occurs in `text`, overlaps included.
inline int Occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace acdplan::test
