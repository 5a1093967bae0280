#pragma once
// Numbers as text, one way for each use: messages and pictures, tables, files read back, counts
// of things. All are locale independent.

#include <string>

namespace acdplan {

/// `value` with at most `digits` significant digits, as printf's "%.<digits>g": "0.5",
/// "1.25", "1e+06". Messages use 15 digits, tables 3-6, CSV files 17 (a read gives back the
/// same double).
std::string FormatSignificant(double value, int digits);

/// `value` with exactly `decimals` digits after the point, as printf's "%.<decimals>f".
std::string FormatFixed(double value, int decimals);

/// The shortest text that reads back as the same double ("0.1", "1e+300"): for files that
/// are read again, such as workspace YAML.
std::string FormatShortest(double value);

/// `count` and `noun`, in the plural unless `count` is 1: "1 face", "2 faces"; nouns ending in
/// -ex, -ch, -sh, -s, -x or consonant + y take their English plural ("2 vertices", "2 patches",
/// "2 meshes", "2 boxes", "2 cavities").
std::string Plural(long long count, const std::string& noun);

}  // namespace acdplan
