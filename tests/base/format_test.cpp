#include "base/format.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>

#include "base/input_error.h"
#include "base/json_number.h"

namespace acdplan {
namespace {

TEST(FormatSignificant, IsPrintfG) {
  EXPECT_EQ(FormatSignificant(0.5, 15), "0.5");
  EXPECT_EQ(FormatSignificant(1.0 / 3.0, 3), "0.333");
  EXPECT_EQ(FormatSignificant(1e6, 6), "1e+06");
  EXPECT_EQ(FormatSignificant(0.1, 17), "0.10000000000000001");
  EXPECT_EQ(FormatSignificant(-2.5, 6), "-2.5");
}

TEST(FormatFixed, KeepsTheDecimals) {
  EXPECT_EQ(FormatFixed(2.0, 1), "2.0");
  EXPECT_EQ(FormatFixed(0.125, 2), "0.12");  // round-half-even of the binary value
  EXPECT_EQ(FormatFixed(1e308, 0).size(), 309u);
}

TEST(FormatShortest, ReadsBackExactly) {
  EXPECT_EQ(FormatShortest(0.1), "0.1");
  EXPECT_EQ(FormatShortest(1e300), "1e+300");
  for (double x : {1.0 / 3.0, 123456.789e-20, std::numeric_limits<double>::denorm_min()}) {
    EXPECT_EQ(std::strtod(FormatShortest(x).c_str(), nullptr), x);
  }
}

TEST(Plural, EnglishPluralsOfTheNounsWeCount) {
  EXPECT_EQ(Plural(1, "face"), "1 face");
  EXPECT_EQ(Plural(0, "face"), "0 faces");
  EXPECT_EQ(Plural(2, "pinch vertex"), "2 pinch vertices");
  EXPECT_EQ(Plural(3, "patch"), "3 patches");
  EXPECT_EQ(Plural(2, "mesh"), "2 meshes");
  EXPECT_EQ(Plural(2, "box"), "2 boxes");
  EXPECT_EQ(Plural(2, "cavity"), "2 cavities");
  EXPECT_EQ(Plural(2, "key"), "2 keys");  // A vowel before the y.
}

TEST(JsonNumber, NullUnlessFinite) {
  EXPECT_EQ(JsonNumber(1.5).dump(), "1.5");
  EXPECT_EQ(JsonNumber(std::numeric_limits<double>::quiet_NaN()).dump(), "null");
  EXPECT_EQ(JsonNumber(std::numeric_limits<double>::infinity()).dump(), "null");
}

TEST(UnknownName, ListsTheKnownNames) {
  EXPECT_EQ(UnknownName("planner", "PRN", {"PRM", "RRT"}),
            "unknown planner 'PRN' (expected one of: PRM, RRT)");
  EXPECT_EQ(JoinNames({}), "");
}

}  // namespace
}  // namespace acdplan
