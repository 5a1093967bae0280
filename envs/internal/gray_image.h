#pragma once
// Small readers for the grey images of occupancy maps.

#include <cstdint>
#include <string>
#include <vector>

namespace acdplan::envs::internal {

/// A grey image in row-major order, row 0 at the top.
struct GrayImage {
  int width = 0, height = 0;
  int max_value = 255;                ///< The value of white.
  std::vector<std::uint16_t> pixels;  ///< width * height values in [0, max_value].
};

/// Reads a PGM image, plain (P2) or binary (P5), maxval 1..65535, '#' comments in the header.
/// @throws InputError "<path>: <rule>" (missing file, bad magic, malformed header,
///         truncated data, value above maxval).
GrayImage ReadPgm(const std::string& path);

/// Reads a PNG image with libpng, converted to 8-bit grey (colour by luminance, alpha dropped).
/// @throws InputError "<path>: cannot read PNG: <reason>".
GrayImage ReadPng(const std::string& path);

/// ReadPgm() or ReadPng() by the file's first bytes (PNG signature, else PGM).
GrayImage ReadGrayImage(const std::string& path);

}  // namespace acdplan::envs::internal
