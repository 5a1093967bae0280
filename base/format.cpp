#include "base/format.h"

#include <charconv>
#include <cstdio>

namespace acdplan {

std::string FormatSignificant(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

std::string FormatFixed(double value, int decimals) {
  char buffer[384];  // "%.f" of 1e308 has 309 digits.
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string FormatShortest(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string Plural(long long count, const std::string& noun) {
  std::string plural = noun + "s";
  if (noun.size() >= 2 && noun.compare(noun.size() - 2, 2, "ex") == 0) {
    plural = noun.substr(0, noun.size() - 2) + "ices";  // vertex
  } else if (noun.size() >= 2 && (noun.compare(noun.size() - 2, 2, "ch") == 0 ||
                                  noun.compare(noun.size() - 2, 2, "sh") == 0 ||
                                  noun.back() == 's' || noun.back() == 'x')) {
    plural = noun + "es";  // patch, mesh, class, box
  } else if (noun.size() >= 2 && noun.back() == 'y' && noun[noun.size() - 2] != 'e') {
    plural = noun.substr(0, noun.size() - 1) + "ies";  // cavity
  }
  return std::to_string(count) + " " + (count == 1 ? noun : plural);
}

}  // namespace acdplan
