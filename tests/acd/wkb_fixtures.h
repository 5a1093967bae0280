#pragma once
// Well-Known Binary and GeoPackageBinary written by hand, in either byte order, for the WKB and
// GeoPackage readers' tests.

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::test {

/// Appends WKB's words in one byte order.
class WkbWriter {
 public:
  explicit WkbWriter(bool little_endian = true) : little_endian_(little_endian) {}

  /// A geometry's start: the byte order and the type word.
  WkbWriter& Header(std::uint32_t type) {
    bytes_.push_back(little_endian_ ? '\1' : '\0');
    return Word(type);
  }
  WkbWriter& Word(std::uint32_t value) { return Append(value, 4); }
  WkbWriter& Double(double value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return Append(bits, 8);
  }
  /// A point count, then the points, each with `extra` further coordinates (z, m).
  WkbWriter& Points(const acd::Ring2d& points, int extra = 0) {
    Word(static_cast<std::uint32_t>(points.size()));
    for (const acd::Point2d& p : points) {
      Double(p.x()).Double(p.y());
      for (int k = 0; k < extra; ++k) Double(7.0 + k);
    }
    return *this;
  }
  /// A ring as written: its points and the first again.
  WkbWriter& Ring(acd::Ring2d ring, int extra = 0) {
    ring.push_back(ring.front());
    return Points(ring, extra);
  }
  /// A whole Polygon geometry of `type` (3, or 1003 / 2003 / 3003 with `extra` coordinates).
  WkbWriter& Polygon(const std::vector<acd::Ring2d>& rings, std::uint32_t type = 3, int extra = 0) {
    Header(type).Word(static_cast<std::uint32_t>(rings.size()));
    for (const acd::Ring2d& ring : rings) Ring(ring, extra);
    return *this;
  }
  WkbWriter& Raw(const std::string& bytes) {
    bytes_ += bytes;
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  WkbWriter& Append(std::uint64_t value, int size) {
    for (int k = 0; k < size; ++k) {
      const int shift = 8 * (little_endian_ ? k : size - 1 - k);
      bytes_.push_back(static_cast<char>((value >> shift) & 0xFF));
    }
    return *this;
  }

  bool little_endian_;
  std::string bytes_;
};

/// A GeoPackageBinary blob: "GP", version 0, the flags (the header's byte order, the envelope
/// kind `envelope` 0 - 4 with that many zero doubles, the empty flag), SRS id 0, then `wkb`.
inline std::string GeoPackageBlob(const std::string& wkb, int envelope = 1,
                                  bool little_endian_header = true, bool empty = false) {
  static const int kDoubles[] = {0, 4, 6, 6, 8};
  std::string blob = "GP";
  blob.push_back('\0');
  blob.push_back(
      static_cast<char>((little_endian_header ? 1 : 0) | (envelope << 1) | (empty ? 0x10 : 0)));
  WkbWriter header(little_endian_header);
  header.Word(0);
  for (int k = 0; k < kDoubles[envelope]; ++k) header.Double(0.0);
  return blob + header.bytes() + wkb;
}

}  // namespace acdplan::test
