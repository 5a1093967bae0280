#pragma once
// The problems a decomposition check reports: the first few in full, then a count.

#include <string>
#include <utility>
#include <vector>

namespace acdplan::acd::internal {

/// Collects problem lines, keeping the first `limit` and counting the rest ("... and N more"),
/// so a badly broken input gives a readable report rather than millions of lines.
class ProblemList {
 public:
  explicit ProblemList(size_t limit = 50) : limit_(limit) {}
  void Add(std::string line) {
    ++count_;
    if (lines_.size() < limit_) lines_.push_back(std::move(line));
  }
  std::vector<std::string> Finish() && {
    if (count_ > lines_.size()) {
      lines_.push_back("... and " + std::to_string(count_ - lines_.size()) + " more");
    }
    return std::move(lines_);
  }

 private:
  size_t limit_;
  std::vector<std::string> lines_;
  size_t count_ = 0;
};

}  // namespace acdplan::acd::internal
