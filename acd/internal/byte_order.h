#pragma once
// Numbers stored in a binary file's bytes, in either byte order: the readers of the ESRI
// shapefile (.shp, both orders) and of its dBase attribute table (.dbf, little-endian).

#include <cstdint>
#include <cstring>
#include <string_view>

namespace acdplan::acd::internal {

/// The byte at offset `at` of `bytes`, as 0-255. The caller checks the bounds.
inline std::uint32_t ByteAt(std::string_view bytes, std::int64_t at) {
  return static_cast<unsigned char>(bytes[static_cast<size_t>(at)]);
}

/// The unsigned integer of `count` (at most 4) bytes from `at`, least significant first.
inline std::uint32_t LittleEndianUnsigned(std::string_view bytes, std::int64_t at, int count) {
  std::uint32_t value = 0;
  for (int k = count - 1; k >= 0; --k) value = value << 8 | ByteAt(bytes, at + k);
  return value;
}

/// The unsigned integer of 4 bytes from `at`, most significant first.
inline std::uint32_t BigEndianUnsigned32(std::string_view bytes, std::int64_t at) {
  std::uint32_t value = 0;
  for (int k = 0; k < 4; ++k) value = value << 8 | ByteAt(bytes, at + k);
  return value;
}

/// The IEEE 754 double of 8 bytes from `at`, least significant first.
inline double LittleEndianDouble(std::string_view bytes, std::int64_t at) {
  std::uint64_t bits = 0;
  for (int k = 7; k >= 0; --k) bits = bits << 8 | ByteAt(bytes, at + k);
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace acdplan::acd::internal
