#include "envs/obj_off_reader.h"

#include <algorithm>
#include <climits>
#include <string_view>
#include <vector>

#include "acd/internal/text_parsing.h"
#include "acd/internal/triangulate_ring.h"
#include "base/input_error.h"

namespace acdplan::envs {
namespace {

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
  switch (acd::internal::ParseDouble(word, value)) {
    case acd::internal::NumberStatus::kOk:
      return value;
    case acd::internal::NumberStatus::kMalformed:
      break;
    case acd::internal::NumberStatus::kNotFinite:
      where.Fail("coordinate '" + std::string(word) + "' is not finite");
    case acd::internal::NumberStatus::kOutOfRange:
      where.Fail("coordinate '" + std::string(word) + "' is beyond the range of doubles");
  }
  where.Fail("malformed number '" + std::string(word) + "'");
}

// The vertex whose coordinates are words[first, first + 3).
Eigen::Vector3d ParseVertex(const Words& words, size_t first, const Where& where) {
  if (words.size() < first + 3) {
    where.Fail("a vertex needs 3 coordinates, got " + std::to_string(words.size() - first));
  }
  return {ParseCoordinate(words[first], where), ParseCoordinate(words[first + 1], where),
          ParseCoordinate(words[first + 2], where)};
}

// A mesh's vertices and polygonal faces as read; Finish() triangulates them.
class PolygonSoup {
 public:
  std::vector<Eigen::Vector3d> vertices;

  // A face of 0-based vertex indices, checked by the reader.
  void AddFace(const std::vector<int>& corners) {
    corners_.insert(corners_.end(), corners.begin(), corners.end());
    face_ends_.push_back(corners_.size());
  }

  // The triangles of every face; vertices no face uses dropped, the others in their order.
  acd::TriangleMesh Finish(const std::string& source) const {
    std::vector<Eigen::Vector3i> triangles;
    std::vector<int> face;
    for (size_t f = 0, begin = 0; f < face_ends_.size(); begin = face_ends_[f++]) {
      face.assign(corners_.begin() + static_cast<std::ptrdiff_t>(begin),
                  corners_.begin() + static_cast<std::ptrdiff_t>(face_ends_[f]));
      AppendTriangles(face, &triangles);
    }
    if (triangles.empty()) throw InputError(source + ": no triangles in file");
    std::vector<int> index(vertices.size(), -1);
    for (const Eigen::Vector3i& t : triangles) {
      for (const int v : t) index[v] = 0;
    }
    std::vector<Eigen::Vector3d> used;
    for (size_t v = 0; v < vertices.size(); ++v) {
      if (index[v] == 0) {
        index[v] = static_cast<int>(used.size());
        used.push_back(vertices[v]);
      }
    }
    for (Eigen::Vector3i& t : triangles) t = Eigen::Vector3i(index[t[0]], index[t[1]], index[t[2]]);
    acd::TriangleMesh mesh = acd::MakeTriangleMesh(used, triangles);
    acd::CheckTriangleMesh(mesh, source);
    return mesh;
  }

 private:
  // Triangles of the face, counter-clockwise about its normal as the face is. Projected along
  // its Newell normal's largest axis, a strictly convex face is fanned from its first corner,
  // as other OBJ readers do (the choice of diagonals matters where modellers leave faces
  // non-planar, or overlapping each other); any other face is ear-clipped (a fan if it has no
  // area at all).
  void AppendTriangles(const std::vector<int>& face, std::vector<Eigen::Vector3i>* out) const {
    const size_t k = face.size();
    if (k == 3) {
      out->emplace_back(face[0], face[1], face[2]);
      return;
    }
    // Relative to the first corner: a face 4.5e6 from the origin keeps its small features.
    const Eigen::Vector3d& origin = vertices[face[0]];
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (size_t i = 1; i + 1 < k; ++i) {
      normal += (vertices[face[i]] - origin).cross(vertices[face[i + 1]] - origin);
    }
    int axis = 0;
    normal.cwiseAbs().maxCoeff(&axis);
    if (normal[axis] == 0.0) {
      for (size_t i = 1; i + 1 < k; ++i) out->emplace_back(face[0], face[i], face[i + 1]);
      return;
    }
    // (u, v, axis) is right-handed when the normal points along +axis: the face projects
    // counter-clockwise either way.
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    if (normal[axis] < 0.0) std::swap(u, v);
    acd::Ring2d ring;
    ring.reserve(k);
    for (const int corner : face) {
      const Eigen::Vector3d p = vertices[corner] - origin;
      ring.emplace_back(p[u], p[v]);
    }
    bool strictly_convex = true;
    for (size_t i = 0; i < k && strictly_convex; ++i) {
      const acd::Point2d& a = ring[i];
      const acd::Point2d& b = ring[(i + 1) % k];
      const acd::Point2d& c = ring[(i + 2) % k];
      strictly_convex = (b - a).x() * (c - b).y() - (b - a).y() * (c - b).x() > 0.0;
    }
    if (strictly_convex) {
      for (size_t i = 1; i + 1 < k; ++i) out->emplace_back(face[0], face[i], face[i + 1]);
      return;
    }
    for (const std::array<int, 3>& t : acd::internal::TriangulateRing(ring)) {
      out->emplace_back(face[t[0]], face[t[1]], face[t[2]]);
    }
  }

  std::vector<int> corners_;       // The faces' corners, one face after the other.
  std::vector<size_t> face_ends_;  // Where each face's corners end in corners_.
};

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
