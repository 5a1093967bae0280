#pragma once
// The "name  value" lines of the command line's reports (`acdplan decompose`, `acdplan env`).

#include <string>

namespace acdplan::tools {

/// A number in a report: at most 6 significant digits ("0.5", "1.25e-07").
std::string ReportNumber(double value);

/// Prints the lines of one report on stdout, each name padded to the same width so that the
/// values line up: `const ReportLines line(14); line("components", "3");`.
class ReportLines {
 public:
  explicit constexpr ReportLines(int name_width) : name_width_(name_width) {}
  void operator()(const char* name, const std::string& value) const;

 private:
  int name_width_;
};

}  // namespace acdplan::tools
