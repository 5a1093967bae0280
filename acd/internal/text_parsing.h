#pragma once
// Small text helpers shared by the text readers (the polygon readers in acd/, and envs/'s OBJ,
// OFF, PLY, Moving AI map and OMPL.app problem readers) and PreparePolygon()'s messages. Not part
// of the public API.

#include <istream>
#include <string>
#include <string_view>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Outcome of ParseDouble().
enum class NumberStatus {
  kOk,          ///< `value` holds a finite number.
  kMalformed,   ///< The token is not one number, e.g. "-6.64248.788605" or "1,5".
  kNotFinite,   ///< The token spells NaN or infinity.
  kOutOfRange,  ///< The number overflows a double, e.g. "1e400".
};

/// Parses the whole of `token` as a decimal floating-point number (locale independent; a
/// leading '+' is accepted). Sets `value` only on kOk.
NumberStatus ParseDouble(std::string_view token, double& value);

/// ParseDouble() the way it is taken where the standard library has no floating-point
/// std::from_chars (libc++ before LLVM 20): the same grammar checked by hand, the value read
/// by strtod_l in the "C" locale. POSIX systems only. Declared so that tests compare the two
/// ways where both exist.
NumberStatus ParseDoubleWithoutFromChars(std::string_view token, double& value);

/// The rule `token` breaks as messages name it: "malformed number '1,5'", "non-finite number
/// 'nan'", "number out of range '1e400'"; empty for kOk.
std::string NumberProblem(NumberStatus status, std::string_view token);

/// Parses the whole of `token` as a decimal integer (a leading '+' is accepted).
bool ParseInt(std::string_view token, long long& value);

/// Formats `p` as "(x, y)", each with up to 15 significant digits (as messages show numbers).
std::string FormatPoint(const Point2d& p);

/// Consumes a UTF-8 byte order mark (EF BB BF, which Windows editors write) at the start of
/// `in`, so that a reader sees the text as written; other input is left as it is.
void SkipByteOrderMark(std::istream& in);

/// Lower-cases ASCII letters.
std::string ToLower(std::string_view text);

}  // namespace acdplan::acd::internal
