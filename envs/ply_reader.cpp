#include "envs/ply_reader.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <optional>
#include <string_view>
#include <vector>

#include "acd/internal/text_parsing.h"
#include "base/input_error.h"
#include "envs/internal/polygon_soup.h"
#include "envs/internal/text_words.h"

namespace acdplan::envs {
namespace {

using internal::PolygonSoup;

// PLY's number types.
enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

std::optional<Type> TypeNamed(std::string_view name) {
  // The names of the original specification, then those of later writers (rply, VTK).
  static constexpr std::array<std::pair<std::string_view, Type>, 16> kNames{{
      {"char", Type::kInt8},
      {"uchar", Type::kUint8},
      {"short", Type::kInt16},
      {"ushort", Type::kUint16},
      {"int", Type::kInt32},
      {"uint", Type::kUint32},
      {"float", Type::kFloat32},
      {"double", Type::kFloat64},
      {"int8", Type::kInt8},
      {"uint8", Type::kUint8},
      {"int16", Type::kInt16},
      {"uint16", Type::kUint16},
      {"int32", Type::kInt32},
      {"uint32", Type::kUint32},
      {"float32", Type::kFloat32},
      {"float64", Type::kFloat64},
  }};
  for (const auto& [spelled, type] : kNames) {
    if (spelled == name) return type;
  }
  return std::nullopt;
}

bool IsInteger(Type type) { return type != Type::kFloat32 && type != Type::kFloat64; }

// What a property is to the mesh.
enum class Role { kSkip, kX, kY, kZ, kCorners };

struct Property {
  std::string name;
  Type type = Type::kFloat32;  // Of the value, or of a list's items.
  bool list = false;
  Type count_type = Type::kUint8;  // Of a list's length.
  Role role = Role::kSkip;
};

struct Element {
  std::string name;
  long long count = 0;
  int line = 0;  // Of its declaration.
  std::vector<Property> properties;
};

enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct Header {
  Format format = Format::kAscii;
  std::vector<Element> elements;
  int lines = 0;
  long long vertex_count = 0;
};

[[noreturn]] void FailAt(const std::string& source, int line, const std::string& rule) {
  throw InputError(source + ":" + std::to_string(line) + ": " + rule);
}

// The whitespace-separated words of `line`.
std::vector<std::string_view> HeaderWords(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

// The header, through "end_header"; `in` is left at the first byte of the data. The roles of
// the vertex coordinates and the face corners are set, and checked to be there.
Header ReadHeader(std::istream& in, const std::string& source) {
  Header header;
  std::string line;
  auto next = [&] {
    if (!std::getline(in, line)) {
      FailAt(source, header.lines, "the header does not end (no 'end_header' line)");
    }
    ++header.lines;
    if (!line.empty() && line.back() == '\r') line.pop_back();
  };
  acd::internal::SkipByteOrderMark(in);
  if (!std::getline(in, line) || (line != "ply" && line != "ply\r")) {
    throw InputError(source + ":1: not a PLY file (its first line must be 'ply')");
  }
  header.lines = 1;
  bool has_format = false;
  for (;;) {
    next();
    const std::vector<std::string_view> words = HeaderWords(line);
    const int at = header.lines;
    if (words.size() == 1 && words[0] == "end_header") break;
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "format") {
      if (words.size() != 3 || words[2] != "1.0") {
        FailAt(source, at, "expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      }
      if (words[1] == "ascii") {
        header.format = Format::kAscii;
      } else if (words[1] == "binary_little_endian") {
        header.format = Format::kBinaryLittleEndian;
      } else if (words[1] == "binary_big_endian") {
        header.format = Format::kBinaryBigEndian;
      } else {
        FailAt(source, at, "unknown format '" + std::string(words[1]) + "'");
      }
      has_format = true;
    } else if (words[0] == "element") {
      long long count = 0;
      if (words.size() != 3 || !acd::internal::ParseInt(words[2], count) || count < 0) {
        FailAt(source, at, "expected 'element <name> <count>', the count a whole number >= 0");
      }
      for (const Element& e : header.elements) {
        if (e.name == words[1]) FailAt(source, at, "element '" + e.name + "' declared twice");
      }
      header.elements.push_back({std::string(words[1]), count, at, {}});
    } else if (words[0] == "property") {
      if (header.elements.empty()) FailAt(source, at, "a property before any element");
      Property property;
      const bool list = words.size() == 5 && words[1] == "list";
      if (words.size() != 3 && !list) {
        FailAt(source, at,
               "expected 'property <type> <name>' or 'property list <type> <type> "
               "<name>'");
      }
      const size_t type_at = list ? 3 : 1;
      for (const size_t k : list ? std::vector<size_t>{2, 3} : std::vector<size_t>{1}) {
        if (!TypeNamed(words[k])) {
          FailAt(source, at, "unknown property type '" + std::string(words[k]) + "'");
        }
      }
      property.list = list;
      property.type = *TypeNamed(words[type_at]);
      if (list) property.count_type = *TypeNamed(words[2]);
      if (list && !IsInteger(property.count_type)) {
        FailAt(source, at,
               "a list's length must have an integer type, not '" + std::string(words[2]) + "'");
      }
      property.name = std::string(words.back());
      Element& element = header.elements.back();
      for (const Property& p : element.properties) {
        if (p.name == property.name) {
          FailAt(source, at,
                 "property '" + p.name + "' of element '" + element.name + "' declared twice");
        }
      }
      if (element.name == "vertex" && !list) {
        if (property.name == "x") property.role = Role::kX;
        if (property.name == "y") property.role = Role::kY;
        if (property.name == "z") property.role = Role::kZ;
      }
      if (element.name == "face" && list &&
          (property.name == "vertex_indices" || property.name == "vertex_index")) {
        if (!IsInteger(property.type)) {
          FailAt(source, at,
                 "vertex indices must have an integer type, not '" + std::string(words[3]) + "'");
        }
        const bool other = std::any_of(element.properties.begin(), element.properties.end(),
                                       [](const Property& p) { return p.role == Role::kCorners; });
        if (!other) property.role = Role::kCorners;
      }
      element.properties.push_back(std::move(property));
    } else {
      FailAt(source, at, "unknown header keyword '" + std::string(words[0]) + "'");
    }
  }
  if (!has_format) FailAt(source, header.lines, "the header has no 'format' line");
  const Element* vertex = nullptr;
  const Element* face = nullptr;
  for (const Element& e : header.elements) {
    if (e.name == "vertex") vertex = &e;
    if (e.name == "face") face = &e;
    if (e.name == "tristrips" && e.count > 0) {
      FailAt(source, e.line,
             "triangle strips ('tristrips') are not read: they would be lost "
             "(export faces)");
    }
  }
  if (face == nullptr || face->count == 0) throw InputError(source + ": no triangles in file");
  if (vertex == nullptr) {
    FailAt(source, face->line, "faces but no element 'vertex' for them to refer to");
  }
  const std::array<std::pair<Role, const char*>, 3> axes{
      {{Role::kX, "x"}, {Role::kY, "y"}, {Role::kZ, "z"}}};
  for (const auto& [role, name] : axes) {
    if (std::none_of(vertex->properties.begin(), vertex->properties.end(),
                     [role = role](const Property& p) { return p.role == role; })) {
      FailAt(source, vertex->line, std::string("element 'vertex' has no property '") + name + "'");
    }
  }
  if (std::none_of(face->properties.begin(), face->properties.end(),
                   [](const Property& p) { return p.role == Role::kCorners; })) {
    FailAt(source, face->line, "element 'face' has no list property 'vertex_indices'");
  }
  if (vertex->count > INT_MAX) {
    FailAt(source, vertex->line, "more than " + std::to_string(INT_MAX) + " vertices");
  }
  header.vertex_count = vertex->count;
  return header;
}

// The data of an ASCII file: whitespace-separated words, one record per line by custom (not
// required here), positions by line.
class AsciiData {
 public:
  AsciiData(std::string text, const std::string& source, int header_lines)
      : words_(std::move(text), header_lines + 1), source_(source) {}

  void Begin(const Element& element, long long index) {
    element_ = &element;
    index_ = index;
  }

  double Number(Type) {
    const std::string_view word = Next();
    double value = 0.0;
    const acd::internal::NumberStatus status = acd::internal::ParseDouble(word, value);
    if (status != acd::internal::NumberStatus::kOk) {
      Fail(acd::internal::NumberProblem(status, word));
    }
    return value;
  }

  long long Integer(Type) {
    const std::string_view word = Next();
    long long value = 0;
    if (!acd::internal::ParseInt(word, value)) {
      Fail("malformed integer '" + std::string(word) + "'");
    }
    return value;
  }

  // Nothing but white space may follow the declared elements.
  void End() {
    std::string_view word;
    if (words_.Next(&word)) {
      Fail("unexpected '" + std::string(word) + "' after the declared elements (wrong count?)");
    }
  }

  [[noreturn]] void Fail(const std::string& rule) const { FailAt(source_, words_.Line(), rule); }

 private:
  std::string_view Next() {
    std::string_view word;
    if (!words_.Next(&word)) {
      Fail("the file ends inside " + element_->name + " " + std::to_string(index_) + " of the " +
           std::to_string(element_->count) + " declared on line " + std::to_string(element_->line));
    }
    return word;
  }

  internal::TextWords words_;
  const std::string& source_;
  const Element* element_ = nullptr;
  long long index_ = 0;
};

// The data of a binary file, in either byte order; positions by element and index.
class BinaryData {
 public:
  BinaryData(std::string bytes, const std::string& source, bool big_endian)
      : bytes_(std::move(bytes)), source_(source), swap_(big_endian != HostIsBigEndian()) {}

  void Begin(const Element& element, long long index) {
    element_ = &element;
    index_ = index;
  }

  double Number(Type type) {
    switch (type) {
      case Type::kFloat32:
        return Read<float>();
      case Type::kFloat64:
        return Read<double>();
      default:
        return static_cast<double>(Integer(type));
    }
  }

  long long Integer(Type type) {
    switch (type) {
      case Type::kInt8:
        return Read<std::int8_t>();
      case Type::kUint8:
        return Read<std::uint8_t>();
      case Type::kInt16:
        return Read<std::int16_t>();
      case Type::kUint16:
        return Read<std::uint16_t>();
      case Type::kInt32:
        return Read<std::int32_t>();
      case Type::kUint32:
        return Read<std::uint32_t>();
      default:  // The header allows integer types only where integers are read.
        break;
    }
    Fail("an integer was expected");
  }

  // Nothing but line ends and spaces (which some writers append) may follow the data.
  void End() const {
    const size_t rest = bytes_.find_first_not_of(" \r\n", pos_);
    if (rest != std::string::npos) {
      throw InputError(source_ + ": " + std::to_string(bytes_.size() - pos_) +
                       " bytes after the declared elements (wrong count?)");
    }
  }

  [[noreturn]] void Fail(const std::string& rule) const {
    throw InputError(source_ + ": " + element_->name + " " + std::to_string(index_) + ": " + rule);
  }

 private:
  static bool HostIsBigEndian() {
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 0;
  }

  template <typename T>
  T Read() {
    if (bytes_.size() - pos_ < sizeof(T)) {
      Fail("the file ends inside it (" + std::to_string(element_->count) + " declared on line " +
           std::to_string(element_->line) + ")");
    }
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), bytes_.data() + pos_, sizeof(T));
    if (swap_) std::reverse(raw.begin(), raw.end());
    pos_ += sizeof(T);
    T value;
    std::memcpy(&value, raw.data(), sizeof(T));
    return value;
  }

  std::string bytes_;
  const std::string& source_;
  bool swap_;
  size_t pos_ = 0;
  const Element* element_ = nullptr;
  long long index_ = 0;
};

template <typename Data>
acd::TriangleMesh ReadData(const Header& header, Data& data, const std::string& source) {
  PolygonSoup soup;
  soup.vertices.reserve(static_cast<size_t>(std::min(header.vertex_count, 1LL << 20)));
  std::vector<int> corners;
  for (const Element& element : header.elements) {
    const bool vertex = element.name == "vertex";
    for (long long index = 0; index < element.count; ++index) {
      data.Begin(element, index);
      Eigen::Vector3d point = Eigen::Vector3d::Zero();
      for (const Property& property : element.properties) {
        if (!property.list) {
          const double value = data.Number(property.type);
          if (property.role == Role::kSkip) continue;
          if (!std::isfinite(value)) data.Fail("coordinate " + property.name + " is not finite");
          point[static_cast<int>(property.role) - static_cast<int>(Role::kX)] = value;
          continue;
        }
        const long long length = data.Integer(property.count_type);
        if (length < 0) data.Fail("list '" + property.name + "' has a negative length");
        if (property.role != Role::kCorners) {
          for (long long i = 0; i < length; ++i) data.Number(property.type);
          continue;
        }
        if (length < 3) {
          data.Fail("a face needs at least 3 corners, got " + std::to_string(length));
        }
        corners.clear();
        for (long long i = 0; i < length; ++i) {
          const long long corner = data.Integer(property.type);
          if (corner < 0 || corner >= header.vertex_count) {
            data.Fail("face refers to vertex " + std::to_string(corner) +
                      (header.vertex_count > 0 ? ", but the vertices are 0 to " +
                                                     std::to_string(header.vertex_count - 1)
                                               : ", but the file has no vertices"));
          }
          corners.push_back(static_cast<int>(corner));
        }
        soup.AddFace(corners);
      }
      if (vertex) soup.vertices.push_back(point);
    }
  }
  data.End();
  return soup.Finish(source);
}

}  // namespace

acd::TriangleMesh ReadPly(std::istream& in, const std::string& source) {
  const Header header = ReadHeader(in, source);
  std::string rest{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (header.format == Format::kAscii) {
    AsciiData data(std::move(rest), source, header.lines);
    return ReadData(header, data, source);
  }
  BinaryData data(std::move(rest), source, header.format == Format::kBinaryBigEndian);
  return ReadData(header, data, source);
}

}  // namespace acdplan::envs
