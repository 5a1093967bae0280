#pragma once
// The whitespace-separated words of a text and the line each is on: how the ASCII PLY and STL
// readers walk their data, which need not keep to one record per line.

#include <string>
#include <string_view>

namespace acdplan::envs::internal {

class TextWords {
 public:
  /// `text` starts on line `first_line`.
  TextWords(std::string text, int first_line) : text_(std::move(text)), line_(first_line) {}

  /// The next word; false at the end of the text, where Line() stays the last word's line.
  bool Next(std::string_view* word) {
    const int before = line_;
    SkipSpace();
    if (pos_ >= text_.size()) {
      line_ = before;  // A message then names the last line with a word, not the empty end.
      return false;
    }
    size_t end = pos_;
    while (end < text_.size() && !IsSpace(text_[end])) ++end;
    *word = std::string_view(text_).substr(pos_, end - pos_);
    pos_ = end;
    return true;
  }

  /// Skips what is left of the current line.
  void SkipLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }

  /// The line of the last word read (or of the start).
  int Line() const { return line_; }

 private:
  static bool IsSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  }

  void SkipSpace() {
    while (pos_ < text_.size() && IsSpace(text_[pos_])) {
      if (text_[pos_++] == '\n') ++line_;
    }
  }

  std::string text_;
  int line_;
  size_t pos_ = 0;
};

}  // namespace acdplan::envs::internal
