#include "acd/shapefile_reader.h"

#include <cmath>
#include <cstdint>
#include <utility>

#include "acd/internal/byte_order.h"
#include "acd/internal/ring_nesting.h"
#include "base/file_io.h"
#include "base/format.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

// The format's fixed numbers (ESRI Shapefile Technical Description, 1998).
constexpr std::int64_t kHeaderBytes = 100;
constexpr std::int64_t kRecordHeaderBytes = 8;
constexpr std::int64_t kPolygonFixedBytes = 44;  // Type, box, NumParts, NumPoints.
constexpr std::int32_t kFileCode = 9994;
constexpr std::int32_t kVersion = 1000;
constexpr std::int32_t kNullShape = 0;

bool IsPolygonType(std::int32_t type) { return type == 5 || type == 15 || type == 25; }

std::string ShapeTypeName(std::int32_t type) {
  switch (type) {
    case 0:
      return "Null";
    case 1:
      return "Point";
    case 3:
      return "PolyLine";
    case 5:
      return "Polygon";
    case 8:
      return "MultiPoint";
    case 11:
      return "PointZ";
    case 13:
      return "PolyLineZ";
    case 15:
      return "PolygonZ";
    case 18:
      return "MultiPointZ";
    case 21:
      return "PointM";
    case 23:
      return "PolyLineM";
    case 25:
      return "PolygonM";
    case 28:
      return "MultiPointM";
    case 31:
      return "MultiPatch";
    default:
      return "unknown";
  }
}

// The file's bytes with the format's two byte orders, bounds checked by the caller.
class Bytes {
 public:
  explicit Bytes(std::string data) : data_(std::move(data)) {}
  std::int64_t size() const { return static_cast<std::int64_t>(data_.size()); }
  std::int32_t BigEndianInt(std::int64_t at) const {
    return static_cast<std::int32_t>(internal::BigEndianUnsigned32(data_, at));
  }
  std::int32_t LittleEndianInt(std::int64_t at) const {
    return static_cast<std::int32_t>(internal::LittleEndianUnsigned(data_, at, 4));
  }
  double LittleEndianDouble(std::int64_t at) const {
    return internal::LittleEndianDouble(data_, at);
  }

 private:
  std::string data_;
};

// The rings of a polygon record (named `record` in messages) whose content, after the record
// header, starts at byte `at` and holds `length` bytes. Rings written without their closing
// point are counted in `unclosed`, the first named in `first_unclosed`.
std::vector<Ring2d> RecordRings(const Bytes& bytes, std::int64_t at, std::int64_t length,
                                const std::string& record, long long* unclosed,
                                std::string* first_unclosed) {
  if (length < kPolygonFixedBytes) {
    throw InputError(record + ": a polygon record needs at least " +
                     std::to_string(kPolygonFixedBytes) + " bytes, it holds " +
                     std::to_string(length));
  }
  const std::int64_t parts = bytes.LittleEndianInt(at + 36);
  const std::int64_t points = bytes.LittleEndianInt(at + 40);
  if (parts < 0 || points < 0) {
    throw InputError(record + ": negative NumParts (" + std::to_string(parts) + ") or NumPoints (" +
                     std::to_string(points) + ")");
  }
  const std::int64_t needed = kPolygonFixedBytes + 4 * parts + 16 * points;
  if (needed > length) {
    throw InputError(record + ": NumParts " + std::to_string(parts) + " and NumPoints " +
                     std::to_string(points) + " need " + std::to_string(needed) +
                     " bytes, the record holds " + std::to_string(length));
  }
  if (parts == 0 && points > 0) {
    throw InputError(record + ": " + std::to_string(points) + " points in no part");
  }
  const std::int64_t point_bytes = at + kPolygonFixedBytes + 4 * parts;
  std::vector<Ring2d> rings;
  for (std::int64_t p = 0; p < parts; ++p) {
    const std::int64_t begin = bytes.LittleEndianInt(at + kPolygonFixedBytes + 4 * p);
    const std::int64_t end =
        p + 1 < parts ? bytes.LittleEndianInt(at + kPolygonFixedBytes + 4 * (p + 1)) : points;
    const std::string part = record + ", part " + std::to_string(p);
    if (p == 0 && begin != 0) {
      throw InputError(part + ": the first part starts at point " + std::to_string(begin) +
                       ", not 0");
    }
    if (!(begin < end && end <= points)) {
      throw InputError(part + ": its points run from index " + std::to_string(begin) + " to " +
                       std::to_string(end) + ", which is empty or past NumPoints " +
                       std::to_string(points));
    }
    Ring2d ring;
    ring.reserve(static_cast<size_t>(end - begin));
    for (std::int64_t k = begin; k < end; ++k) {
      const Point2d point(bytes.LittleEndianDouble(point_bytes + 16 * k),
                          bytes.LittleEndianDouble(point_bytes + 16 * k + 8));
      if (!std::isfinite(point.x()) || !std::isfinite(point.y())) {
        throw InputError(part + ", point " + std::to_string(k - begin) + ": non-finite coordinate");
      }
      ring.push_back(point);
    }
    if (ring.size() >= 2 && ring.front() == ring.back()) {
      ring.pop_back();
    } else if ((*unclosed)++ == 0) {
      *first_unclosed = part;
    }
    rings.push_back(std::move(ring));
  }
  return rings;
}

}  // namespace

std::vector<Polygon2d> ReadShapefile(std::istream& in, const std::string& source,
                                     std::vector<int>* multipolygons,
                                     std::vector<std::string>* warnings,
                                     std::vector<int>* features) {
  const Bytes bytes(ReadRest(in));
  if (bytes.size() < kHeaderBytes) {
    throw InputError(source + ": not a shapefile: " + std::to_string(bytes.size()) +
                     " bytes, shorter than the 100-byte header");
  }
  if (bytes.BigEndianInt(0) != kFileCode) {
    throw InputError(source + ": not a shapefile: file code " +
                     std::to_string(bytes.BigEndianInt(0)) + " at byte 0, expected 9994");
  }
  if (bytes.LittleEndianInt(28) != kVersion) {
    throw InputError(source + ": unsupported shapefile version " +
                     std::to_string(bytes.LittleEndianInt(28)) + " at byte 28, expected 1000");
  }
  const std::int32_t file_type = bytes.LittleEndianInt(32);
  if (file_type != kNullShape && !IsPolygonType(file_type)) {
    throw InputError(source + ": holds " + ShapeTypeName(file_type) + " shapes (type " +
                     std::to_string(file_type) +
                     "), not polygons: acdplan reads Polygon, PolygonZ and PolygonM shapefiles");
  }
  // The declared length counts 16-bit words.
  const std::int64_t declared = 2 * static_cast<std::int64_t>(bytes.BigEndianInt(24));
  if (declared > bytes.size() || declared < kHeaderBytes) {
    throw InputError(source + ": the header declares " + std::to_string(declared) +
                     " bytes, the file holds " + std::to_string(bytes.size()) +
                     (declared > bytes.size() ? ": truncated" : ""));
  }
  if (declared < bytes.size() && warnings != nullptr) {
    warnings->push_back(source + ": " + std::to_string(bytes.size() - declared) +
                        " bytes after the length the header declares (" + std::to_string(declared) +
                        "): ignored");
  }
  std::vector<Polygon2d> polygons;
  std::vector<int> groups;
  std::vector<int> records;    // Per polygon: its record's index from 0.
  long long unclosed = 0;      // Rings written without their closing point,
  std::string first_unclosed;  // and the first of them.
  std::int64_t at = kHeaderBytes;
  for (int number = 1; at < declared; ++number) {
    const std::string record = source + ": record " + std::to_string(number);
    if (declared - at < kRecordHeaderBytes) {
      throw InputError(record + " (byte " + std::to_string(at) + "): header cut off after " +
                       std::to_string(declared - at) + " of its 8 bytes");
    }
    const std::int64_t length = 2 * static_cast<std::int64_t>(bytes.BigEndianInt(at + 4));
    const std::int64_t content = at + kRecordHeaderBytes;
    if (length < 4 || length > declared - content) {
      throw InputError(record + " (byte " + std::to_string(at) + "): content length " +
                       std::to_string(length) + " bytes " +
                       (length < 4
                            ? "is too short for a shape type"
                            : "runs past the end of the file (" +
                                  std::to_string(declared - content) + " bytes left): truncated"));
    }
    at = content + length;
    const std::int32_t type = bytes.LittleEndianInt(content);
    if (type == kNullShape) continue;
    if (type != file_type) {
      throw InputError(record + ": shape type " + ShapeTypeName(type) + " (" +
                       std::to_string(type) + ") differs from the file's, " +
                       ShapeTypeName(file_type) + " (" + std::to_string(file_type) + ")");
    }
    const std::vector<Ring2d> rings =
        RecordRings(bytes, content, length, record, &unclosed, &first_unclosed);
    if (rings.empty()) continue;
    std::vector<Polygon2d> members = internal::PolygonsByNesting(rings);
    const int group = members.size() > 1 ? number : -1;
    for (Polygon2d& member : members) {
      polygons.push_back(std::move(member));
      groups.push_back(group);
      records.push_back(number - 1);
    }
  }
  if (unclosed > 0 && warnings != nullptr) {  // One line, however many.
    warnings->push_back(first_unclosed +
                        ": ring not closed (the format repeats its first point last); read as "
                        "closed" +
                        (unclosed > 1 ? " (and " + Plural(unclosed - 1, "more ring") + " like it)"
                                      : std::string()));
  }
  if (multipolygons != nullptr) *multipolygons = std::move(groups);
  if (features != nullptr) *features = std::move(records);
  return polygons;
}

}  // namespace acdplan::acd
