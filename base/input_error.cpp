#include "base/input_error.h"

namespace acdplan {

std::string JoinNames(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

std::string UnknownName(const std::string& what, const std::string& name,
                        const std::vector<std::string>& known) {
  return "unknown " + what + " '" + name + "' (expected one of: " + JoinNames(known) + ")";
}

}  // namespace acdplan
