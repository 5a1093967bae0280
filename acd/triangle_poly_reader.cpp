#include "acd/triangle_poly_reader.h"

#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "acd/internal/even_odd_regions.h"
#include "acd/internal/text_parsing.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

// A line that holds data: its words (comments, from '#', removed) and its number in the file.
struct Line {
  std::vector<std::string> words;
  int number = 0;
};

// The lines of `text` that hold data, up to `limit` of them.
std::vector<Line> DataLines(const std::string& text, size_t limit = SIZE_MAX) {
  std::istringstream in(text);
  internal::SkipByteOrderMark(in);
  std::vector<Line> lines;
  std::string line;
  for (int number = 1; lines.size() < limit && std::getline(in, line); ++number) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    Line data{{}, number};
    for (std::string word; words >> word;) data.words.push_back(word);
    if (!data.words.empty()) lines.push_back(std::move(data));
  }
  return lines;
}

bool IsInteger(const std::string& word) {
  long long value = 0;
  return internal::ParseInt(word, value);
}

// Reads one file's sections line by line; every message names the file and the line.
class SectionReader {
 public:
  SectionReader(std::vector<Line> lines, std::string source)
      : lines_(std::move(lines)), source_(std::move(source)) {}

  [[noreturn]] void Fail(int line, const std::string& rule) const {
    throw InputError(source_ + ":" + std::to_string(line) + ": " + rule);
  }

  bool AtEnd() const { return next_ >= lines_.size(); }

  // The next data line, with at least `fields` words (what it must hold is `expected`).
  const Line& Next(const std::string& expected, size_t fields) {
    if (AtEnd()) {
      Fail(lines_.empty() ? 1 : lines_.back().number,
           "unexpected end of file: expected " + expected);
    }
    const Line& line = lines_[next_++];
    if (line.words.size() < fields) {
      Fail(line.number,
           "expected " + expected + ", found " + std::to_string(line.words.size()) + " field(s)");
    }
    return line;
  }

  long long Integer(const Line& line, size_t field, const std::string& what, long long lo,
                    long long hi) const {
    long long value = 0;
    const std::string& word = line.words[field];
    if (!internal::ParseInt(word, value))
      Fail(line.number, "malformed " + what + " '" + word + "'");
    if (value < lo || value > hi) {
      Fail(line.number,
           what + " " + word + " out of range " + std::to_string(lo) + ".." + std::to_string(hi));
    }
    return value;
  }

  double Number(const Line& line, size_t field) const {
    double value = 0.0;
    const internal::NumberStatus status = internal::ParseDouble(line.words[field], value);
    if (status != internal::NumberStatus::kOk) {
      Fail(line.number, internal::NumberProblem(status, line.words[field]));
    }
    return value;
  }

  // The vertex section: its header, then a line per vertex. The first vertex's number (0 or 1)
  // is returned in `first_number`; a count of 0 returns no vertex.
  std::vector<Point2d> Vertices(int* first_number) {
    const Line& header =
        Next("a header '<vertices> <dimension> [<attributes> [<boundary markers>]]'", 1);
    // A count beyond the file is reported as a truncated file below.
    const long long count = Integer(header, 0, "vertex count", 0, kMaxCount);
    if (header.words.size() >= 2) {
      const long long dimension = Integer(header, 1, "dimension", 0, kMaxCount);
      if (dimension != 2) {
        Fail(header.number,
             "dimension must be 2, found " + header.words[1] +
                 (dimension == 3 ? " (a 3D .poly is TetGen's, which is not read)" : ""));
      }
    }
    if (header.words.size() >= 3) Integer(header, 2, "attribute count", 0, kMaxCount);
    if (header.words.size() >= 4) Integer(header, 3, "boundary marker count", 0, 1);
    std::vector<Point2d> vertices;
    for (long long k = 0; k < count; ++k) {
      const Line& line = Next("vertex " + std::to_string(k + 1) + " of " + std::to_string(count) +
                                  " ('<number> <x> <y> ...')",
                              3);
      if (k == 0) *first_number = static_cast<int>(Integer(line, 0, "first vertex number", 0, 1));
      if (k > 0) Integer(line, 0, "vertex number", 0, kMaxCount);
      vertices.emplace_back(Number(line, 1), Number(line, 2));
    }
    return vertices;
  }

  static constexpr long long kMaxCount = 1LL << 31;

 private:
  std::vector<Line> lines_;
  std::string source_;
  size_t next_ = 0;
};

}  // namespace

bool IsTrianglePoly(const std::string& text) {
  const std::vector<Line> lines = DataLines(text, 3);  // Enough for three words.
  if (lines.empty()) return false;
  const std::vector<std::string>& header = lines.front().words;
  if (header.size() < 2 || header.size() > 4) return false;
  for (const std::string& word : header) {
    if (!IsInteger(word)) return false;
  }
  // Lien's chain count may share its line with the first chain's vertex count.
  std::vector<std::string> words;
  for (const Line& line : lines) {
    words.insert(words.end(), line.words.begin(), line.words.end());
    if (words.size() >= 3) break;
  }
  const std::string third = words.size() >= 3 ? internal::ToLower(words[2]) : "";
  return third != "out" && third != "in";
}

std::vector<Polygon2d> ReadTrianglePoly(const std::string& text, const std::string& source) {
  SectionReader poly(DataLines(text), source);
  int first = 0;
  std::vector<Point2d> vertices = poly.Vertices(&first);
  std::string vertex_file = source;
  if (vertices.empty()) {  // Triangle's convention: the vertices are in the .node file.
    vertex_file = std::filesystem::path(source).replace_extension(".node").string();
    if (const std::string reason = UnreadableFileReason(vertex_file); !reason.empty()) {
      throw InputError(source + ":1: the vertex count is 0, so the vertices are in " + vertex_file +
                       ", which cannot be read: " + reason);
    }
    vertices = SectionReader(DataLines(ReadFile(vertex_file)), vertex_file).Vertices(&first);
  }
  const long long n = static_cast<long long>(vertices.size());
  const Line& header = poly.Next("a header '<segments> [<boundary markers>]'", 1);
  const long long segment_count = poly.Integer(header, 0, "segment count", 0, poly.kMaxCount);
  if (header.words.size() >= 2) poly.Integer(header, 1, "boundary marker count", 0, 1);
  std::vector<std::pair<Point2d, Point2d>> segments;
  for (long long k = 0; k < segment_count; ++k) {
    const Line& line =
        poly.Next("segment " + std::to_string(k + 1) + " of " + std::to_string(segment_count) +
                      " ('<number> <endpoint> <endpoint> ...')",
                  3);
    const std::string what = "endpoint of segment " + line.words[0] + " (a vertex number)";
    if (n == 0)
      poly.Fail(line.number, "segment " + line.words[0] + " but no vertex in " + vertex_file);
    const long long a = poly.Integer(line, 1, what, first, first + n - 1);
    const long long b = poly.Integer(line, 2, what, first, first + n - 1);
    segments.emplace_back(vertices[static_cast<size_t>(a - first)],
                          vertices[static_cast<size_t>(b - first)]);
  }
  const Line& holes_header = poly.Next("the hole count", 1);
  const long long hole_count = poly.Integer(holes_header, 0, "hole count", 0, poly.kMaxCount);
  std::vector<Point2d> holes;
  std::vector<int> hole_lines;
  for (long long k = 0; k < hole_count; ++k) {
    const Line& line = poly.Next("hole " + std::to_string(k + 1) + " of " +
                                     std::to_string(hole_count) + " ('<number> <x> <y>')",
                                 3);
    holes.emplace_back(poly.Number(line, 1), poly.Number(line, 2));
    hole_lines.push_back(line.number);
  }
  // The regional attributes and area constraints that may follow serve meshing only.
  const internal::BoundedRegions regions = internal::RegionsOfSegmentGraph(segments, holes);
  if (regions.hole_on_segment >= 0) {
    poly.Fail(hole_lines[static_cast<size_t>(regions.hole_on_segment)],
              "hole " + std::to_string(regions.hole_on_segment + 1) +
                  " lies on a segment (a hole point must lie inside the region it empties)");
  }
  if (regions.polygons.empty()) {
    throw InputError(source + ": the " + std::to_string(segment_count) +
                     " segment(s) enclose no region (Triangle keeps only what closed loops of "
                     "segments enclose, less the regions of hole points)");
  }
  return regions.polygons;
}

}  // namespace acdplan::acd
