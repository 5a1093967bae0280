#include "envs/obj_off_reader.h"

#include <algorithm>
#include <climits>
#include <string_view>
#include <vector>

#include "acd/internal/text_parsing.h"
#include "base/input_error.h"
#include "envs/internal/polygon_soup.h"

namespace acdplan::envs {
namespace {

using internal::PolygonSoup;
using Words = std::vector<std::string_view>;

// The whitespace-separated words of `line`, a comment ('#' to the end) removed.
void SplitWords(std::string_view line, Words* words) {
  words->clear();
  line = line.substr(0, line.find('#'));
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && space(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !space(line[i])) ++i;
    if (i > start) words->push_back(line.substr(start, i - start));
  }
}

// The input's name and the line being read, for messages.
struct Where {
  const std::string& source;
  int line = 0;

  [[noreturn]] void Fail(const std::string& rule) const {
    throw InputError(source + ":" + std::to_string(line) + ": " + rule);
  }
};

double ParseCoordinate(std::string_view word, const Where& where) {
  double value = 0.0;
  const acd::internal::NumberStatus status = acd::internal::ParseDouble(word, value);
  if (status != acd::internal::NumberStatus::kOk) {
    where.Fail(acd::internal::NumberProblem(status, word));
  }
  return value;
}

// The vertex whose coordinates are words[first, first + 3).
Eigen::Vector3d ParseVertex(const Words& words, size_t first, const Where& where) {
  if (words.size() < first + 3) {
    where.Fail("a vertex needs 3 coordinates, got " + std::to_string(words.size() - first));
  }
  return {ParseCoordinate(words[first], where), ParseCoordinate(words[first + 1], where),
          ParseCoordinate(words[first + 2], where)};
}

// The vertex count must stay an int (TriangleMesh's indices).
void CheckVertexCount(size_t count, const Where& where) {
  if (count > static_cast<size_t>(INT_MAX)) {
    where.Fail("more than " + std::to_string(INT_MAX) + " vertices");
  }
}

}  // namespace

acd::TriangleMesh ReadObj(std::istream& in, const std::string& source) {
  PolygonSoup soup;
  // Faces keep 1-based or relative indices until every vertex is read: a positive index may
  // name a vertex defined further down.
  struct Face {
    int line;
    std::vector<long long> corners;  // 0-based, maybe out of range.
  };
  std::vector<Face> faces;
  Where where{source};
  Words words;
  std::string line, statement;
  int next_line = 0;
  acd::internal::SkipByteOrderMark(in);
  // A line without its comment and its CR.
  auto content = [](std::string* text) {
    text->resize(std::min(text->size(), text->find('#')));
    if (!text->empty() && text->back() == '\r') text->pop_back();
  };
  while (std::getline(in, line)) {
    where.line = ++next_line;
    content(&line);
    statement = line;
    // A statement ending in '\' continues on the next line (not a comment ending in one).
    while (!statement.empty() && statement.back() == '\\') {
      statement.back() = ' ';
      if (!std::getline(in, line)) break;
      ++next_line;
      content(&line);
      statement += line;
    }
    SplitWords(statement, &words);
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (keyword == "v") {
      soup.vertices.push_back(ParseVertex(words, 1, where));
      CheckVertexCount(soup.vertices.size(), where);
    } else if (keyword == "f" || keyword == "fo") {
      if (words.size() < 4) {
        where.Fail("a face needs at least 3 corners, got " + std::to_string(words.size() - 1));
      }
      Face face{where.line, {}};
      for (size_t i = 1; i < words.size(); ++i) {
        const std::string_view corner = words[i];
        long long index = 0;
        if (!acd::internal::ParseInt(corner.substr(0, corner.find('/')), index)) {
          where.Fail("malformed face corner '" + std::string(corner) +
                     "' (expected v, v/vt, v//vn or v/vt/vn)");
        }
        if (index == 0) {
          where.Fail("face corner '" + std::string(corner) +
                     "': OBJ vertex indices start at 1 (or count back from -1)");
        }
        const long long read = static_cast<long long>(soup.vertices.size());
        if (index < 0 && index < -read) {
          where.Fail("face corner '" + std::string(corner) +
                     "' counts back past the first vertex (" + std::to_string(read) +
                     " read so far)");
        }
        face.corners.push_back(index < 0 ? read + index : index - 1);
      }
      faces.push_back(std::move(face));
    } else if (keyword == "surf") {
      where.Fail("free-form surfaces ('surf') are not read: they would be lost (export polygons)");
    }
    // Anything else carries no surface: vt, vn, vp, l, p, g, o, s, mtllib, usemtl, ...
  }
  std::vector<int> corners;
  for (const Face& face : faces) {
    where.line = face.line;
    corners.clear();
    for (const long long index : face.corners) {
      if (index >= static_cast<long long>(soup.vertices.size())) {
        where.Fail("face refers to vertex " + std::to_string(index + 1) + ", but the file has " +
                   std::to_string(soup.vertices.size()) + " vertices");
      }
      corners.push_back(static_cast<int>(index));
    }
    soup.AddFace(corners);
  }
  return soup.Finish(source);
}

acd::TriangleMesh ReadOff(std::istream& in, const std::string& source) {
  Where where{source};
  Words words;
  std::string line;
  acd::internal::SkipByteOrderMark(in);
  // The next line with words on it; false at the end of the input.
  auto next = [&] {
    while (std::getline(in, line)) {
      ++where.line;
      SplitWords(line, &words);
      if (!words.empty()) return true;
    }
    return false;
  };
  if (!next()) throw InputError(source + ": no triangles in file");
  size_t first_count = 0;  // Where the counts start in `words`.
  long long ignored = 0;
  if (!acd::internal::ParseInt(words[0], ignored)) {
    // Geomview's header: [ST][C][N][4][n]OFF, then BINARY for the binary form.
    const std::string_view header = words[0];
    if (header.size() < 3 || acd::internal::ToLower(header.substr(header.size() - 3)) != "off") {
      where.Fail("expected the OFF header or the vertex count, got '" + std::string(header) + "'");
    }
    const std::string_view prefix = header.substr(0, header.size() - 3);
    if (prefix.find_first_of("4n") != std::string_view::npos) {
      where.Fail("'" + std::string(header) + "' is not 3D: only 3D OFF is read");
    }
    if (prefix.find_first_not_of("STCN") != std::string_view::npos) {
      where.Fail("unknown OFF header '" + std::string(header) + "'");
    }
    if (words.size() > 1 && words[1] == "BINARY") {
      where.Fail("binary OFF is not read (write it as text)");
    }
    if (words.size() > 1) {
      first_count = 1;  // "OFF 8 6 0" on one line.
    } else if (!next()) {
      where.Fail("the file ends before the vertex, face and edge counts");
    }
  }
  const int counts_line = where.line;
  long long vertex_count = 0, face_count = 0;
  if (words.size() < first_count + 2 ||
      !acd::internal::ParseInt(words[first_count], vertex_count) ||
      !acd::internal::ParseInt(words[first_count + 1], face_count) || vertex_count < 0 ||
      face_count < 0) {
    std::string got;
    for (size_t i = first_count; i < words.size(); ++i) {
      got += (i > first_count ? " " : "") + std::string(words[i]);
    }
    where.Fail("expected the vertex, face and edge counts, got '" + got + "'");
  }
  CheckVertexCount(static_cast<size_t>(vertex_count), where);
  auto ended = [&](const char* what, long long read, long long declared) {
    where.Fail("the file ends after " + std::to_string(read) + " of the " +
               std::to_string(declared) + " " + what + " declared on line " +
               std::to_string(counts_line));
  };
  PolygonSoup soup;
  soup.vertices.reserve(static_cast<size_t>(std::min(vertex_count, 1LL << 20)));
  for (long long v = 0; v < vertex_count; ++v) {
    if (!next()) ended("vertices", v, vertex_count);
    soup.vertices.push_back(ParseVertex(words, 0, where));
  }
  std::vector<int> corners;
  for (long long f = 0; f < face_count; ++f) {
    if (!next()) ended("faces", f, face_count);
    long long k = 0;
    if (!acd::internal::ParseInt(words[0], k) || k < 3) {
      where.Fail("a face starts with its number of corners, at least 3, got '" +
                 std::string(words[0]) + "'");
    }
    if (static_cast<long long>(words.size()) - 1 < k) {
      where.Fail("a face of " + std::to_string(k) + " corners lists " +
                 std::to_string(words.size() - 1));
    }
    corners.clear();
    for (long long i = 1; i <= k; ++i) {
      long long index = 0;
      if (!acd::internal::ParseInt(words[i], index)) {
        where.Fail("malformed vertex index '" + std::string(words[i]) + "'");
      }
      if (index < 0 || index >= vertex_count) {
        where.Fail("face refers to vertex " + std::to_string(index) +
                   ", but the vertices are 0 to " + std::to_string(vertex_count - 1));
      }
      corners.push_back(static_cast<int>(index));
    }
    soup.AddFace(corners);
  }
  if (next()) {
    where.Fail("unexpected '" + std::string(words[0]) + "' after the " +
               std::to_string(face_count) + " faces declared on line " +
               std::to_string(counts_line) + " (wrong count?)");
  }
  return soup.Finish(source);
}

}  // namespace acdplan::envs
