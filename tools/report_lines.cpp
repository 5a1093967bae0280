#include "tools/report_lines.h"

#include <cstdio>

#include "base/format.h"

namespace acdplan::tools {

std::string ReportNumber(double value) { return FormatSignificant(value, 6); }

void ReportLines::operator()(const char* name, const std::string& value) const {
  std::printf("%-*s %s\n", name_width_, name, value.c_str());
}

}  // namespace acdplan::tools
