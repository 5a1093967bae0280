#include "acd/wkb_reader.h"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "base/input_error.h"

namespace acdplan::acd {
namespace {

// WKB type codes (OGC 06-103r4 Table 7, ISO 13249-3's curve and surface types).
enum WkbType : std::uint32_t {
  kPoint = 1,
  kLineString = 2,
  kPolygon = 3,
  kMultiPoint = 4,
  kMultiLineString = 5,
  kMultiPolygon = 6,
  kGeometryCollection = 7,
  kCircularString = 8,
  kCompoundCurve = 9,
  kCurvePolygon = 10,
  kMultiCurve = 11,
  kMultiSurface = 12,
  kCurve = 13,    // Abstract: never written.
  kSurface = 14,  // Abstract: never written.
  kPolyhedralSurface = 15,
  kTin = 16,
  kTriangle = 17,
};

const char* TypeName(std::uint32_t type) {
  static const char* const kNames[] = {"Geometry",
                                       "Point",
                                       "LineString",
                                       "Polygon",
                                       "MultiPoint",
                                       "MultiLineString",
                                       "MultiPolygon",
                                       "GeometryCollection",
                                       "CircularString",
                                       "CompoundCurve",
                                       "CurvePolygon",
                                       "MultiCurve",
                                       "MultiSurface",
                                       "Curve",
                                       "Surface",
                                       "PolyhedralSurface",
                                       "TIN",
                                       "Triangle"};
  return type < sizeof(kNames) / sizeof(kNames[0]) ? kNames[type] : "unknown";
}

constexpr int kMaxDepth = 32;

// A cursor over the bytes of one WKB geometry, reading in the byte order of the geometry at hand.
class WkbParser {
 public:
  WkbParser(const unsigned char* data, size_t size, const std::string& where)
      : data_(data), size_(size), where_(where) {}

  WkbPolygons Parse() {
    Nest(ReadHeader(), /*depth=*/0, /*member_of=*/-1);
    if (at_ != size_) Fail(at_, std::to_string(size_ - at_) + " bytes after the geometry");
    return std::move(out_);
  }

 private:
  // The header of a geometry: its byte order and type word.
  struct Header {
    std::uint32_t type = 0;  // The base type (1 - 17).
    int coordinates = 2;     // Per point: 2, 3 (z or m) or 4.
    size_t offset = 0;       // Where the geometry starts, for messages.
  };

  [[noreturn]] void Fail(size_t offset, const std::string& rule) const {
    throw InputError(where_ + ": WKB byte " + std::to_string(offset) + ": " + rule);
  }

  void Need(size_t bytes, const char* what) const {
    if (size_ - at_ < bytes) {
      Fail(at_, std::string("truncated: ") + what + " needs " + std::to_string(bytes) + " bytes, " +
                    std::to_string(size_ - at_) + " left");
    }
  }

  std::uint64_t Word(int bytes, const char* what) {
    Need(static_cast<size_t>(bytes), what);
    std::uint64_t value = 0;
    for (int k = 0; k < bytes; ++k) {
      const std::uint64_t byte = data_[at_ + (little_endian_ ? bytes - 1 - k : k)];
      value = (value << 8) | byte;
    }
    at_ += static_cast<size_t>(bytes);
    return value;
  }

  std::uint32_t Count(const char* what, size_t bytes_each) {
    const size_t offset = at_;
    const auto count = static_cast<std::uint32_t>(Word(4, what));
    // Every element takes at least `bytes_each` bytes: a count beyond what is left is damage,
    // caught before anything that large is allocated.
    if (bytes_each > 0 && count > (size_ - at_) / bytes_each) {
      Fail(offset, std::string("truncated: ") + std::to_string(count) + " " + what + " need " +
                       "at least " + std::to_string(bytes_each) + " bytes each, " +
                       std::to_string(size_ - at_) + " left");
    }
    return count;
  }

  double Coordinate() {
    const size_t offset = at_;
    const std::uint64_t bits = Word(8, "a coordinate");
    double value = 0.0;
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isfinite(value)) Fail(offset, "non-finite coordinate");
    return value;
  }

  Header ReadHeader() {
    Header header;
    header.offset = at_;
    Need(1, "a byte order");
    const unsigned char order = data_[at_++];
    if (order > 1) {
      Fail(header.offset, "byte order " + std::to_string(order) + " (expected 0 or 1)");
    }
    little_endian_ = order == 1;
    std::uint32_t word = static_cast<std::uint32_t>(Word(4, "a geometry type"));
    // PostGIS's extended WKB: flags in the top bits (z 0x80000000, m 0x40000000, SRID
    // 0x20000000); ISO's codes: 1000 z, 2000 m, 3000 z and m.
    const bool ewkb_z = (word & 0x80000000u) != 0, ewkb_m = (word & 0x40000000u) != 0;
    const bool ewkb_srid = (word & 0x20000000u) != 0;
    word &= 0x0FFFFFFFu;
    const std::uint32_t iso = word / 1000;
    header.type = word % 1000;
    if (iso > 3 || header.type == 0 || header.type > kTriangle) {
      Fail(header.offset, "unknown geometry type " + std::to_string(word));
    }
    header.coordinates =
        2 + (ewkb_z || iso == 1 || iso == 3 ? 1 : 0) + (ewkb_m || iso == 2 || iso == 3 ? 1 : 0);
    if (ewkb_srid) Word(4, "an SRID");
    return header;
  }

  Ring2d Points(const Header& header, bool ring) {
    const size_t point_bytes = 8 * static_cast<size_t>(header.coordinates);
    const std::uint32_t count = Count("points", point_bytes);
    Ring2d points;
    points.reserve(count);
    for (std::uint32_t k = 0; k < count; ++k) {
      const double x = Coordinate(), y = Coordinate();
      for (int extra = 2; extra < header.coordinates; ++extra) Coordinate();
      points.emplace_back(x, y);
    }
    if (ring && points.size() >= 2) {
      if (points.front() == points.back()) {
        points.pop_back();
      } else {
        ++out_.unclosed_rings;
      }
    }
    return points;
  }

  // A polygon's rings: counted and written inline (Polygon, Triangle), or each a geometry of
  // its own (CurvePolygon: straight rings only).
  void Polygon(const Header& header, int member_of) {
    const bool curve = header.type == kCurvePolygon;
    const std::uint32_t rings = Count("rings", curve ? 9 : 4);
    Polygon2d polygon;
    for (std::uint32_t r = 0; r < rings; ++r) {
      Ring2d ring;
      if (curve) {
        const Header inner = ReadHeader();
        if (inner.type == kCircularString || inner.type == kCompoundCurve) {
          Fail(inner.offset, std::string("curved ring (") + TypeName(inner.type) +
                                 "): linearize it first (e.g. ogr2ogr -nlt CONVERT_TO_LINEAR)");
        }
        if (inner.type != kLineString) {
          Fail(inner.offset, std::string("a ring must be a curve, found ") + TypeName(inner.type));
        }
        ring = Points(inner, /*ring=*/true);
      } else {
        ring = Points(header, /*ring=*/true);
      }
      if (r == 0) {
        polygon.outer = std::move(ring);
      } else if (!ring.empty()) {
        polygon.holes.push_back(std::move(ring));
      }
    }
    if (polygon.outer.empty()) {
      if (!polygon.holes.empty()) Fail(header.offset, "a polygon with holes but no exterior ring");
      return;  // An empty polygon.
    }
    out_.polygons.push_back(std::move(polygon));
    out_.multipolygons.push_back(member_of);
  }

  // Passes over a geometry without area, checking its structure.
  void SkipNonAreal(const Header& header, int depth) {
    switch (header.type) {
      case kPoint:
        for (int k = 0; k < header.coordinates; ++k) Word(8, "a coordinate");
        return;
      case kLineString:
      case kCircularString:
        Points(header, /*ring=*/false);
        return;
      default: {  // MultiPoint, MultiLineString, CompoundCurve, MultiCurve: members.
        const std::uint32_t members = Count("members", 9);
        for (std::uint32_t k = 0; k < members; ++k) {
          const Header inner = ReadHeader();
          if (inner.type == kPolygon || inner.type == kMultiPolygon ||
              inner.type == kGeometryCollection || inner.type == kCurvePolygon ||
              inner.type == kMultiSurface || inner.type == kTriangle) {
            Fail(inner.offset, std::string("a ") + TypeName(header.type) + " cannot hold a " +
                                   TypeName(inner.type));
          }
          Nest(inner, depth + 1, -1);
        }
      }
    }
  }

  void Nest(const Header& header, int depth, int member_of) {
    if (depth > kMaxDepth) Fail(header.offset, "geometries nested deeper than 32");
    switch (header.type) {
      case kPolygon:
      case kTriangle:
      case kCurvePolygon:
        Polygon(header, member_of);
        return;
      case kMultiPolygon:
      case kMultiSurface: {
        const int group = multipolygons_++;
        const std::uint32_t members = Count("members", 9);
        for (std::uint32_t k = 0; k < members; ++k) {
          const Header inner = ReadHeader();
          const bool allowed = inner.type == kPolygon ||
                               (header.type == kMultiSurface && inner.type == kCurvePolygon);
          if (!allowed) {
            Fail(inner.offset, std::string("a ") + TypeName(header.type) + " cannot hold a " +
                                   TypeName(inner.type));
          }
          Nest(inner, depth + 1, group);
        }
        return;
      }
      case kGeometryCollection: {
        const std::uint32_t members = Count("members", 9);
        for (std::uint32_t k = 0; k < members; ++k) Nest(ReadHeader(), depth + 1, -1);
        return;
      }
      case kPolyhedralSurface:
      case kTin:
        Fail(header.offset, std::string(TypeName(header.type)) +
                                " is a 3D surface, not a polygon (not supported)");
      case kCurve:
      case kSurface:
        Fail(header.offset, std::string("type ") + TypeName(header.type) +
                                " is abstract (a geometry of it is written as a subtype)");
      default:
        break;
    }
    const std::string name = TypeName(header.type);
    bool listed = false;
    for (auto& [type, count] : out_.non_areal) {
      if (type == name) {
        ++count;
        listed = true;
      }
    }
    if (!listed) out_.non_areal.emplace_back(name, 1);
    SkipNonAreal(header, depth);
  }

  const unsigned char* data_;
  size_t size_;
  const std::string& where_;
  size_t at_ = 0;
  bool little_endian_ = true;
  int multipolygons_ = 0;
  WkbPolygons out_;
};

}  // namespace

WkbPolygons ReadWkb(const unsigned char* data, size_t size, const std::string& where) {
  return WkbParser(data, size, where).Parse();
}

}  // namespace acdplan::acd
