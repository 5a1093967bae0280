// acd/internal/text_parsing.h: ParseDouble() reads numbers the same way whether the standard
// library has floating-point std::from_chars (libstdc++) or not (libc++ before LLVM 20, where
// ParseDoubleWithoutFromChars() does the work): the same status for every token and, for
// numbers, the same double bit for bit.

#include "acd/internal/text_parsing.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace acdplan::acd::internal {
namespace {

#if defined(__cpp_lib_to_chars) && (defined(__unix__) || defined(__APPLE__))

// Both ways on `token`: equal statuses, and equal bits where a number was read.
void ExpectSameReading(const std::string& token) {
  double with = -1.0, without = -1.0;
  const NumberStatus a = ParseDouble(token, with);
  const NumberStatus b = ParseDoubleWithoutFromChars(token, without);
  EXPECT_EQ(static_cast<int>(a), static_cast<int>(b)) << "'" << token << "'";
  if (a == NumberStatus::kOk && b == NumberStatus::kOk) {
    EXPECT_EQ(std::memcmp(&with, &without, sizeof with), 0)
        << "'" << token << "': " << with << " vs " << without;
  }
}

TEST(TextParsingTest, BothWaysReadEveryTokenAlike) {
  const std::vector<std::string> tokens = {"0",
                                           "-0",
                                           "+0",
                                           "1",
                                           "-1",
                                           "1.5",
                                           "+2.25",
                                           "++2",
                                           "+-2",
                                           "-+2",
                                           "--2",
                                           "",
                                           "+",
                                           "-",
                                           ".",
                                           "-.",
                                           ".5",
                                           "5.",
                                           "-.5e3",
                                           "1e5",
                                           "1E5",
                                           "1e+5",
                                           "1e-5",
                                           "1e",
                                           "1e+",
                                           "e5",
                                           ".e5",
                                           "1.2.3",
                                           "-6.64248.788605",
                                           "1,5",
                                           " 1",
                                           "1 ",
                                           "0x1p3",
                                           "0x10",
                                           "1e400",
                                           "-1e400",
                                           "1e-400",
                                           "-1e-400",
                                           "4.9406564584124654e-324",
                                           "2.4703282292062327e-324",
                                           "1.7976931348623157e308",
                                           "1.7976931348623158e308",
                                           "1.7976931348623159e308",
                                           "inf",
                                           "-inf",
                                           "INF",
                                           "Infinity",
                                           "-infinity",
                                           "infinit",
                                           "nan",
                                           "-nan",
                                           "NaN",
                                           "nan(123)",
                                           "nan()",
                                           "nan(",
                                           "nanx",
                                           "0.1000000000000000055511151231257827",
                                           "123456789012345678901234567890",
                                           "0.00000000000000000000000000000000000000001",
                                           "7e-1",
                                           "007",
                                           "1d5",
                                           "1f"};
  for (const std::string& token : tokens) ExpectSameReading(token);
}

TEST(TextParsingTest, BothWaysReadRandomNumbersAlike) {
  std::mt19937_64 engine(20261207);
  char text[64];
  for (int k = 0; k < 20000; ++k) {
    // Any bit pattern that is a finite double, written shortest, with 17 digits and with 6.
    std::uint64_t bits = engine();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isfinite(value)) continue;
    const auto written = std::to_chars(text, text + sizeof text, value);
    ExpectSameReading(std::string(text, written.ptr));
    std::snprintf(text, sizeof text, "%.17g", value);
    ExpectSameReading(text);
    std::snprintf(text, sizeof text, "%.6e", value);
    ExpectSameReading(text);
  }
}

#endif

}  // namespace
}  // namespace acdplan::acd::internal
