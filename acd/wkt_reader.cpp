#include "acd/wkt_reader.h"

#include <cctype>
#include <optional>
#include <string>
#include <string_view>

#include "acd/internal/text_parsing.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

// Recursive-descent parser over the whole text (OGC 06-103r4, section 7):
//   text       := ([SRID=integer ;] geometry)*   the SRID prefix of PostGIS's EWKT is skipped
//   geometry   := POLYGON [dim] (EMPTY | polygon)
//               | MULTIPOLYGON [dim] (EMPTY | '(' (EMPTY | polygon) (',' (EMPTY | polygon))* ')')
//               | GEOMETRYCOLLECTION [dim] (EMPTY | '(' geometry (',' geometry)* ')')
//   polygon    := '(' ring (',' ring)* ')'   first ring outer, the others holes
//   ring       := EMPTY | '(' point (',' point)* ')' closed: the last point repeats the first
//   point      := number number [number [number]]   z and m are ignored
//   dim        := Z | M | ZM
class WktParser {
 public:
  WktParser(std::istream& in, const std::string& source) : text_(Text(in)), source_(source) {}

  // The polygons, and per polygon its MULTIPOLYGON and its top-level geometry (ReadWkt()).
  std::vector<Polygon2d> Parse(std::vector<int>* multipolygons, std::vector<int>* features) {
    SkipSpace();
    if (pos_ >= text_.size()) Fail("expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION");
    for (int feature = 0; pos_ < text_.size(); ++feature) {
      SkipSrid();
      ParseGeometry();
      features_.resize(polygons_.size(), feature);
      SkipSpace();
      // Several geometries may follow one another, optionally separated by ';'.
      if (pos_ < text_.size() && text_[pos_] == ';') {
        ++pos_;
        SkipSpace();
      }
    }
    if (multipolygons != nullptr) *multipolygons = std::move(multipolygons_);
    if (features != nullptr) *features = std::move(features_);
    return std::move(polygons_);
  }

 private:
  static std::string Text(std::istream& in) {
    internal::SkipByteOrderMark(in);
    return ReadRest(in);
  }

  [[noreturn]] void Fail(const std::string& message) const { FailAt(pos_, message); }

  [[noreturn]] void FailAt(size_t offset, const std::string& message) const {
    int line = 1;
    size_t line_start = 0;
    for (size_t i = 0; i < offset && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    }
    std::string found = "end of input";
    if (offset < text_.size()) {
      const std::string word = WordAt(offset);
      found = "'" + (word.empty() ? std::string(1, text_[offset]) : word) + "'";
    }
    throw InputError(source_ + ": " + message + " at line " + std::to_string(line) + ", column " +
                     std::to_string(offset - line_start + 1) + ", found " + found);
  }

  static bool IsDelimiter(char c) {
    return std::isspace(static_cast<unsigned char>(c)) || c == '(' || c == ')' || c == ',' ||
           c == ';';
  }

  std::string WordAt(size_t offset) const {
    size_t end = offset;
    while (end < text_.size() && !IsDelimiter(text_[end])) ++end;
    return text_.substr(offset, end - offset);
  }

  void SkipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  std::string PeekWord() {
    SkipSpace();
    return internal::ToLower(WordAt(pos_));
  }

  void Expect(char c) {
    SkipSpace();
    if (pos_ >= text_.size() || text_[pos_] != c) Fail(std::string("expected '") + c + "'");
    ++pos_;
  }

  // Consumes ',' and returns true, or returns false at ')' (left in place); else fails.
  bool CommaOr(char close, const std::string& what) {
    SkipSpace();
    if (pos_ < text_.size() && text_[pos_] == ',') {
      ++pos_;
      return true;
    }
    if (pos_ < text_.size() && text_[pos_] == close) return false;
    Fail("expected ',' or ')' after " + what);
  }

  // Skips an optional dimension word; returns true when the next word is EMPTY (consumed).
  bool DimensionThenEmpty() {
    std::string word = PeekWord();
    if (word == "z" || word == "m" || word == "zm") {
      pos_ += word.size();
      word = PeekWord();
    }
    if (word == "empty") {
      pos_ += word.size();
      return true;
    }
    return false;
  }

  // Skips EWKT's "SRID=4326;": the reference system does not change the planar geometry.
  void SkipSrid() {
    const std::string word = PeekWord();
    if (word.compare(0, 5, "srid=") != 0) return;
    long long srid = 0;
    if (!internal::ParseInt(std::string_view(word).substr(5), srid)) {
      Fail("malformed SRID (expected SRID=<integer>;)");
    }
    pos_ += word.size();
    Expect(';');
  }

  void ParseGeometry() {
    SkipSpace();
    const size_t start = pos_;
    const std::string word = PeekWord();
    if (word == "polygon") {
      pos_ += word.size();
      if (!DimensionThenEmpty()) ParsePolygon();
    } else if (word == "multipolygon") {
      pos_ += word.size();
      if (DimensionThenEmpty()) return;
      Expect('(');
      multipolygon_ = multipolygon_count_++;
      do {
        if (const std::string word = PeekWord(); word == "empty") {
          pos_ += word.size();
        } else {
          ParsePolygon();
        }
      } while (CommaOr(')', "a polygon"));
      Expect(')');
      multipolygon_ = -1;
    } else if (word == "geometrycollection") {
      pos_ += word.size();
      if (DimensionThenEmpty()) return;
      Expect('(');
      do {
        ParseGeometry();
      } while (CommaOr(')', "a geometry"));
      Expect(')');
    } else {
      FailAt(start,
             "expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION (other geometry types "
             "are not supported)");
    }
  }

  // An EMPTY hole adds nothing; an EMPTY exterior ring leaves no polygon, and no hole may
  // follow it (OGC 06-103r4 7.2.4 lets any ring be EMPTY; GEOS refuses holes in an empty shell).
  void ParsePolygon() {
    Expect('(');
    SkipSpace();
    const size_t start = pos_;
    std::optional<Ring2d> outer = ParseRing();
    Polygon2d polygon;
    while (CommaOr(')', "a ring")) {
      if (std::optional<Ring2d> hole = ParseRing()) polygon.holes.push_back(std::move(*hole));
    }
    Expect(')');
    if (!outer) {
      if (!polygon.holes.empty()) FailAt(start, "a polygon with an EMPTY exterior ring has a hole");
      return;
    }
    polygon.outer = std::move(*outer);
    polygons_.push_back(std::move(polygon));
    multipolygons_.push_back(multipolygon_);
  }

  // A ring, or nothing for EMPTY.
  std::optional<Ring2d> ParseRing() {
    if (const std::string word = PeekWord(); word == "empty") {
      pos_ += word.size();
      return std::nullopt;
    }
    Expect('(');
    const size_t start = pos_;
    Ring2d ring;
    do {
      ring.push_back(ParsePoint());
    } while (CommaOr(')', "a point"));
    if (ring.size() < 2 || ring.front() != ring.back()) {
      FailAt(start, "ring is not closed (its last point must repeat its first point " +
                        internal::FormatPoint(ring.front()) + ")");
    }
    ring.pop_back();  // The repeated closing point.
    Expect(')');
    return ring;
  }

  Point2d ParsePoint() {
    double xy[2] = {0.0, 0.0};
    int count = 0;
    while (true) {
      SkipSpace();
      if (pos_ >= text_.size() || IsDelimiter(text_[pos_])) break;
      const size_t start = pos_;
      const std::string word = WordAt(pos_);
      double value = 0.0;
      const internal::NumberStatus status = internal::ParseDouble(word, value);
      if (status != internal::NumberStatus::kOk)
        FailAt(start, internal::NumberProblem(status, word));
      if (count == 4) FailAt(start, "more than 4 coordinates in a point");
      if (count < 2) xy[count] = value;
      ++count;
      pos_ += word.size();
    }
    if (count < 2) Fail("expected a point: two numbers 'x y'");
    return Point2d(xy[0], xy[1]);
  }

  std::string text_;
  const std::string& source_;
  size_t pos_ = 0;
  std::vector<Polygon2d> polygons_;
  std::vector<int> multipolygons_;  // Per polygon.
  std::vector<int> features_;       // Per polygon: its top-level geometry.
  int multipolygon_ = -1;           // The MULTIPOLYGON being read, or -1.
  int multipolygon_count_ = 0;
};

}  // namespace

std::vector<Polygon2d> ReadWkt(std::istream& in, const std::string& source,
                               std::vector<int>* multipolygons, std::vector<int>* features) {
  return WktParser(in, source).Parse(multipolygons, features);
}

}  // namespace acdplan::acd
