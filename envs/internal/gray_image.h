#pragma once
// Readers for the images of occupancy maps, reduced to grey levels as ROS map_server reads them.

#include <cstdint>
#include <string>
#include <vector>

namespace acdplan::envs::internal {

/// What a pixel's alpha channel means to map_server (ROS 1 map_server and Nav2's agree): in
/// trinary mode it is averaged with the colour channels; in scale mode it is left out of the
/// average, and a pixel that is not fully opaque is unknown; raw mode leaves it out.
enum class ImageAlpha {
  kAveraged,  ///< Alpha is one more channel of the mean (trinary mode).
  kSeparate,  ///< The mean is over the colour channels; GrayImage::transparent marks pixels.
};

/// An image in row-major order, row 0 at the top, one grey level per pixel: the mean of its
/// channels (see ImageAlpha), held as their sum, `pixels[i] / max_value` in [0, 1] exactly.
struct GrayImage {
  int width = 0, height = 0;
  std::uint32_t max_value = 255;      ///< The sum at white: channels averaged x the largest value.
  std::vector<std::uint32_t> pixels;  ///< width * height sums in [0, max_value].
  /// With ImageAlpha::kSeparate and an alpha channel: per pixel, 1 where it is not fully
  /// opaque. Empty otherwise.
  std::vector<std::uint8_t> transparent;
};

/// Reads a PGM image (plain P2 or binary P5, maxval 1..65535, '#' comments in the header) or a
/// PNG image (any colour type and bit depth, a palette expanded, read by libpng at 8 bits per
/// channel), chosen by the file's first bytes (the PNG signature, else PGM). A colour pixel's
/// grey level is the plain mean of its red, green and blue values, as map_server takes it (not
/// a luminance). PNG samples are read as written unless the file declares a gamma other than
/// sRGB's (a gAMA chunk of 1.0, as libpng's own writer gives 16-bit files): libpng then
/// converts them to sRGB, where map_server would read them as written.
/// @throws InputError "<path>: <rule>" (missing file, bad magic, malformed header, truncated
///         data, value above maxval, "cannot read PNG: <reason>").
GrayImage ReadGrayImage(const std::string& path, ImageAlpha alpha = ImageAlpha::kAveraged);

}  // namespace acdplan::envs::internal
