#include "acd/poly_reader.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "acd/internal/text_parsing.h"
#include "acd/triangle_poly_reader.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

// A whitespace-separated word of the file, comments ('#' to end of line) removed. The format
// is read word by word, like Lien's reader (acd2d's operator>>): simple3.poly, for instance,
// spreads one vertex order over two lines.
struct Token {
  std::string text;
  int line = 0;
};

class PolyParser {
 public:
  PolyParser(std::istream& in, const std::string& source) : source_(source) {
    internal::SkipByteOrderMark(in);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
      ++number;
      const size_t hash = line.find('#');
      if (hash != std::string::npos) line.resize(hash);
      size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) tokens_.push_back({line.substr(start, i - start), number});
      }
    }
    last_line_ = number;
  }

  std::vector<Polygon2d> Parse(std::vector<std::string>* warnings) {
    const Token& count_token = Next("the number of chains");
    const int chain_count_line = count_token.line;
    const long long chain_count = ReadCount(count_token, "number of chains");
    std::vector<Polygon2d> polygons;
    for (long long chain = 1; chain <= chain_count; ++chain) {
      ReadChain(chain,
                "chain " + std::to_string(chain) + " of " + std::to_string(chain_count) +
                    " (declared on line " + std::to_string(chain_count_line) + ")",
                polygons);
    }
    // Legacy files (Lien's simple5.poly) declare fewer chains than they hold; his reader read
    // the declared ones only. Read what is there when it looks like a chain, and say so once.
    if (next_ < tokens_.size()) {
      const Token& extra = tokens_[next_];
      long long ignored = 0;
      const bool chain_follows = internal::ParseInt(extra.text, ignored) && ignored >= 1 &&
                                 next_ + 1 < tokens_.size() &&
                                 (internal::ToLower(tokens_[next_ + 1].text) == "out" ||
                                  internal::ToLower(tokens_[next_ + 1].text) == "in");
      if (!chain_follows || warnings == nullptr) {
        Fail(extra.line, "unexpected '" + extra.text + "' after the " +
                             std::to_string(chain_count) + " chain(s) declared on line " +
                             std::to_string(chain_count_line) + " (wrong chain count?)");
      }
      const int first_extra_line = extra.line;
      long long chain = chain_count;
      while (next_ < tokens_.size()) {
        ++chain;
        ReadChain(chain,
                  "chain " + std::to_string(chain) + " (beyond the " + std::to_string(chain_count) +
                      " declared on line " + std::to_string(chain_count_line) + ")",
                  polygons);
      }
      warnings->push_back(source_ + ":" + std::to_string(first_extra_line) + ": " +
                          std::to_string(chain - chain_count) + " chain(s) more than the " +
                          std::to_string(chain_count) + " declared on line " +
                          std::to_string(chain_count_line) + "; read all " + std::to_string(chain) +
                          " (wrong chain count in the file)");
    }
    return polygons;
  }

  // Reads chain number `chain` (named `chain_name` in messages) and adds it to `polygons`.
  void ReadChain(long long chain, const std::string& chain_name, std::vector<Polygon2d>& polygons) {
    const Token& size_token = Next("the vertex count of " + chain_name);
    const int header_line = size_token.line;
    const long long n = ReadCount(size_token, "vertex count");
    const Token& kind_token = Next("'out' or 'in' after the vertex count of " + chain_name);
    const std::string kind = internal::ToLower(kind_token.text);
    if (kind != "out" && kind != "in") {
      Fail(kind_token.line,
           "expected 'out' or 'in' after the vertex count, found '" + kind_token.text + "'");
    }
    if (kind == "in" && polygons.empty()) {
      Fail(kind_token.line, "hole chain ('in') before any outer chain ('out')");
    }
    const std::string what =
        "chain " + std::to_string(chain) + " (line " + std::to_string(header_line) + ")";
    Ring2d points;
    // A count larger than the file is reported as a truncated file below; do not trust it
    // for the allocation.
    points.reserve(std::min(static_cast<size_t>(n), tokens_.size()));
    for (long long v = 0; v < n; ++v) {
      const std::string expected =
          "vertex " + std::to_string(v + 1) + " of " + std::to_string(n) + " of " + what;
      const double x = ReadNumber(Next(expected));
      const double y = ReadNumber(Next(expected));
      points.emplace_back(x, y);
    }
    Ring2d ring = ReadOrder(points, what);
    if (kind == "out") {
      polygons.push_back(Polygon2d{std::move(ring), {}});
    } else {
      polygons.back().holes.push_back(std::move(ring));
    }
  }

 private:
  [[noreturn]] void Fail(int line, const std::string& message) const {
    throw InputError(source_ + ":" + std::to_string(line) + ": " + message);
  }

  const Token& Next(const std::string& expected) {
    if (next_ >= tokens_.size()) {
      Fail(last_line_, "unexpected end of file: expected " + expected);
    }
    return tokens_[next_++];
  }

  long long ReadCount(const Token& token, const std::string& what) const {
    long long value = 0;
    if (!internal::ParseInt(token.text, value)) {
      Fail(token.line, "malformed " + what + " '" + token.text + "'");
    }
    if (value < 1) Fail(token.line, what + " must be positive, found " + token.text);
    return value;
  }

  double ReadNumber(const Token& token) const {
    double value = 0.0;
    const internal::NumberStatus status = internal::ParseDouble(token.text, value);
    if (status != internal::NumberStatus::kOk) {
      Fail(token.line, internal::NumberProblem(status, token.text));
    }
    return value;
  }

  // The line after a chain's vertices lists the 1-based vertex indices in boundary order; it
  // must be a permutation of 1..n.
  Ring2d ReadOrder(const Ring2d& points, const std::string& what) {
    const long long n = static_cast<long long>(points.size());
    Ring2d ring;
    ring.reserve(points.size());
    std::vector<int> seen_on_line(points.size(), 0);
    for (long long k = 0; k < n; ++k) {
      const Token& token = Next("index " + std::to_string(k + 1) + " of " + std::to_string(n) +
                                " in the vertex order of " + what);
      long long index = 0;
      if (!internal::ParseInt(token.text, index)) {
        const std::string lower = internal::ToLower(token.text);
        if (lower == "out" || lower == "in") {
          Fail(token.line, "the vertex order of " + what + " ends early: found '" + token.text +
                               "' where index " + std::to_string(k + 1) + " of " +
                               std::to_string(n) + " was expected");
        }
        Fail(token.line,
             "malformed vertex index '" + token.text + "' in the vertex order of " + what);
      }
      if (index < 1 || index > n) {
        Fail(token.line, "vertex index " + token.text + " out of range 1.." + std::to_string(n) +
                             " in the vertex order of " + what);
      }
      int& seen = seen_on_line[static_cast<size_t>(index - 1)];
      if (seen != 0) {
        Fail(token.line, "vertex index " + token.text + " repeated (first on line " +
                             std::to_string(seen) + ") in the vertex order of " + what);
      }
      seen = token.line;
      ring.push_back(points[static_cast<size_t>(index - 1)]);
    }
    return ring;
  }

  const std::string& source_;
  std::vector<Token> tokens_;
  size_t next_ = 0;
  int last_line_ = 0;
};

}  // namespace

std::vector<Polygon2d> ReadPoly(std::istream& in, const std::string& source,
                                std::vector<std::string>* warnings) {
  const std::string text = ReadRest(in);
  if (IsTrianglePoly(text)) return ReadTrianglePoly(text, source);
  std::istringstream lien(text);
  return PolyParser(lien, source).Parse(warnings);
}

}  // namespace acdplan::acd
