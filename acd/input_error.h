#pragma once
// The one exception type for bad user input; the command line maps it to exit status 2.

#include <stdexcept>
#include <string>

namespace acdplan::acd {

/// Thrown when input breaks a documented rule. what() is one line that names the file (or
/// element), the line or element where known, and the rule broken, e.g.
/// "bird.poly:47: malformed number '-6.64248.788605'".
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace acdplan::acd
