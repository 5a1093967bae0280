#include "acd/internal/text_parsing.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "base/format.h"

namespace acdplan::acd::internal {

NumberStatus ParseDouble(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return NumberStatus::kMalformed;
  double parsed = 0.0;
  const char* end = token.data() + token.size();
  // std::from_chars is locale independent (strtod would read "1,5" in a German locale).
  const auto [ptr, ec] = std::from_chars(token.data(), end, parsed);
  if (ptr != end) return NumberStatus::kMalformed;
  if (ec == std::errc::result_out_of_range) {
    // from_chars also reports underflow ("1e-400") as out of range; a tiny number is fine.
    const double magnitude = std::strtod(std::string(token).c_str(), nullptr);
    if (std::isinf(magnitude)) return NumberStatus::kOutOfRange;
    value = magnitude;
    return NumberStatus::kOk;
  }
  if (ec != std::errc()) return NumberStatus::kMalformed;
  if (!std::isfinite(parsed)) return NumberStatus::kNotFinite;
  value = parsed;
  return NumberStatus::kOk;
}

std::string NumberProblem(NumberStatus status, std::string_view token) {
  const std::string quoted = "'" + std::string(token) + "'";
  switch (status) {
    case NumberStatus::kOk:
      break;
    case NumberStatus::kMalformed:
      return "malformed number " + quoted;
    case NumberStatus::kNotFinite:
      return "non-finite number " + quoted;
    case NumberStatus::kOutOfRange:
      return "number out of range " + quoted;
  }
  return "";
}

bool ParseInt(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

std::string FormatPoint(const Point2d& p) {
  return "(" + FormatSignificant(p.x(), 15) + ", " + FormatSignificant(p.y(), 15) + ")";
}

void SkipByteOrderMark(std::istream& in) {
  static constexpr char kMark[] = "\xEF\xBB\xBF";
  for (int k = 0; k < 3; ++k) {
    // A partial mark is no UTF-8 text: what was taken of it the reader would reject anyway.
    if (in.peek() != static_cast<unsigned char>(kMark[k])) return;
    in.get();
  }
}

std::string ToLower(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return lower;
}

}  // namespace acdplan::acd::internal
