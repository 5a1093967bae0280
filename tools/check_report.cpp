#include "tools/check_report.h"

#include <iostream>

namespace acdplan::tools {

int ReportFailedCheck(const std::string& input, const acd::DecompositionCheck& check) {
  std::cerr << "acdplan: internal error: the decomposition of " << input << " failed its check ("
            << check.problems.size() << " problems); no output written:\n";
  for (const std::string& problem : check.problems) std::cerr << "  " << problem << "\n";
  return 1;
}

}  // namespace acdplan::tools
