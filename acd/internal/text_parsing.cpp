#include "acd/internal/text_parsing.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <system_error>

#if defined(__unix__) || defined(__APPLE__)
#include <locale.h>
#if defined(__APPLE__)
#include <xlocale.h>
#endif
#define ACDPLAN_HAS_STRTOD_L 1
#endif

#include "base/format.h"

namespace acdplan::acd::internal {

namespace {

// One leading '+' is accepted (from_chars takes none): false if nothing is left or another
// sign follows.
bool StripPlus(std::string_view& token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  return !token.empty() && token.front() != '+';
}

#if defined(ACDPLAN_HAS_STRTOD_L)
// The decimal numbers std::from_chars reads (chars_format::general): an optional '-', digits
// with at most one '.' (at least one digit), an optional exponent with at least one digit.
bool IsDecimal(std::string_view token) {
  size_t i = token.empty() || token[0] != '-' ? 0 : 1;
  auto digits = [&] {
    const size_t start = i;
    while (i < token.size() && token[i] >= '0' && token[i] <= '9') ++i;
    return i - start;
  };
  size_t mantissa = digits();
  if (i < token.size() && token[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == token.size();
}

// The spellings of infinity and NaN std::from_chars reads.
bool IsNonFinite(std::string_view token) {
  if (!token.empty() && token[0] == '-') token.remove_prefix(1);
  const std::string lower = ToLower(token);
  return lower == "inf" || lower == "infinity" || lower == "nan" ||
         (lower.size() >= 5 && lower.compare(0, 4, "nan(") == 0 && lower.back() == ')');
}
#endif

}  // namespace

#if defined(ACDPLAN_HAS_STRTOD_L)
NumberStatus ParseDoubleWithoutFromChars(std::string_view token, double& value) {
  if (!StripPlus(token)) return NumberStatus::kMalformed;
  if (!IsDecimal(token)) {
    return IsNonFinite(token) ? NumberStatus::kNotFinite : NumberStatus::kMalformed;
  }
  // strtod_l rounds correctly, as from_chars does, and reads '.' whatever locale is set.
  static const locale_t c_locale = newlocale(LC_NUMERIC_MASK, "C", locale_t{});
  const double parsed = strtod_l(std::string(token).c_str(), nullptr, c_locale);
  if (std::isinf(parsed)) return NumberStatus::kOutOfRange;
  value = parsed;
  return NumberStatus::kOk;
}
#endif

NumberStatus ParseDouble(std::string_view token, double& value) {
#if defined(__cpp_lib_to_chars)
  if (!StripPlus(token)) return NumberStatus::kMalformed;
  double parsed = 0.0;
  const char* end = token.data() + token.size();
  // std::from_chars is locale independent (strtod would read "1,5" in a German locale).
  const auto [ptr, ec] = std::from_chars(token.data(), end, parsed);
  if (ptr != end) return NumberStatus::kMalformed;
  if (ec == std::errc::result_out_of_range) {
    // from_chars also reports underflow ("1e-400") as out of range; a tiny number is fine.
#if defined(ACDPLAN_HAS_STRTOD_L)
    return ParseDoubleWithoutFromChars(token, value);  // In the "C" locale, whatever is set.
#else
    const double magnitude = std::strtod(std::string(token).c_str(), nullptr);
    if (std::isinf(magnitude)) return NumberStatus::kOutOfRange;
    value = magnitude;
    return NumberStatus::kOk;
#endif
  }
  if (ec != std::errc()) return NumberStatus::kMalformed;
  if (!std::isfinite(parsed)) return NumberStatus::kNotFinite;
  value = parsed;
  return NumberStatus::kOk;
#else
  // No floating-point from_chars (libc++ before LLVM 20).
  return ParseDoubleWithoutFromChars(token, value);
#endif
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
