#include "envs/internal/gray_image.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::envs::internal {
namespace {

// A cursor over a PGM header: whitespace and '#' comments are skipped between tokens.
class PgmHeader {
 public:
  PgmHeader(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}

  int Integer(const char* what) {
    SkipSpaceAndComments();
    long long value = 0;
    size_t digits = 0;
    while (pos_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[pos_]))) {
      value = value * 10 + (bytes_[pos_++] - '0');
      if (value > 1000000000) break;
      ++digits;
    }
    if (digits == 0 || value > 1000000000) {
      throw InputError(path_ + ": malformed PGM " + (in_header_ ? "header" : "data") +
                       ": expected " + what);
    }
    return static_cast<int>(value);
  }

  void SkipSpaceAndComments() {
    while (pos_ < bytes_.size()) {
      if (bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
        ++pos_;
      } else {
        break;
      }
    }
  }

  size_t pos_ = 2;
  bool in_header_ = true;

 private:
  const std::string& path_;
  const std::string& bytes_;
};

/// A PGM image from the bytes of file `path` (named in messages).
GrayImage PgmFromBytes(const std::string& path, const std::string& bytes) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '2' && bytes[1] != '5')) {
    throw InputError(path + ": not a PGM image (expected magic 'P2' or 'P5')");
  }
  const bool binary = bytes[1] == '5';
  PgmHeader header(path, bytes);
  GrayImage image;
  image.width = header.Integer("width");
  image.height = header.Integer("height");
  const int max_value = header.Integer("maxval");
  if (image.width <= 0 || image.height <= 0) {
    throw InputError(path + ": malformed PGM header: width and height must be > 0");
  }
  if (max_value < 1 || max_value > 65535) {
    throw InputError(path + ": malformed PGM header: maxval must be in [1, 65535]");
  }
  image.max_value = static_cast<std::uint32_t>(max_value);
  // Up to 10^18 pixels by the header; memory is only taken for pixels the file holds.
  const size_t n = static_cast<size_t>(image.width) * image.height;
  if (binary) {
    // Exactly one whitespace byte separates maxval from the raster.
    size_t pos = header.pos_ + 1;
    const size_t bytes_per_pixel = image.max_value > 255 ? 2 : 1;
    if (header.pos_ >= bytes.size() || (bytes.size() - pos) / bytes_per_pixel < n) {
      throw InputError(path + ": truncated PGM data: expected " + std::to_string(n) + " pixels");
    }
    image.pixels.resize(n);
    for (size_t i = 0; i < n; ++i) {
      unsigned value = static_cast<unsigned char>(bytes[pos++]);
      if (bytes_per_pixel == 2) value = (value << 8) | static_cast<unsigned char>(bytes[pos++]);
      image.pixels[i] = value;
    }
  } else {
    header.in_header_ = false;
    for (size_t i = 0; i < n; ++i) {
      header.SkipSpaceAndComments();
      if (header.pos_ >= bytes.size()) {
        throw InputError(path + ": truncated PGM data: expected " + std::to_string(n) +
                         " pixels, found " + std::to_string(i));
      }
      image.pixels.push_back(static_cast<std::uint32_t>(header.Integer("a pixel value")));
    }
  }
  for (size_t i = 0; i < n; ++i) {
    if (image.pixels[i] > image.max_value) {
      throw InputError(path + ": PGM pixel " + std::to_string(i) + " value " +
                       std::to_string(image.pixels[i]) + " exceeds maxval " +
                       std::to_string(image.max_value));
    }
  }
  return image;
}

/// A PNG image from the bytes of file `path` (named in messages).
GrayImage PngFromBytes(const std::string& path, const std::string& bytes, ImageAlpha alpha) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw InputError(path + ": cannot read PNG: " + reason);
  }
  // Deflate expands a byte to at most 1032 bytes, and an output pixel comes from at least one
  // bit of decoded data (1-bit images), so a larger header is a truncated file; rejecting it
  // here keeps a few bytes from asking for gigabytes.
  constexpr size_t kMaxDeflateRatio = 1032;
  const size_t n = static_cast<size_t>(png.width) * png.height;
  if (n / 8 > kMaxDeflateRatio * bytes.size()) {
    png_image_free(&png);
    throw InputError(path + ": cannot read PNG: " + std::to_string(png.width) + " x " +
                     std::to_string(png.height) + " pixels cannot come from " +
                     std::to_string(bytes.size()) + " bytes (truncated file?)");
  }
  // The file's own channels at 8 bits (a palette expanded), so that libpng converts neither
  // colour to grey (it would weigh the channels by luminance) nor gamma: 8-bit output is sRGB,
  // as 8-bit files are taken to be, and 16-bit files are taken as sRGB too rather than linear.
  // Nor does it premultiply alpha, which it does only for 16-bit output.
  png.format = png.format & (PNG_FORMAT_FLAG_COLOR | PNG_FORMAT_FLAG_ALPHA);
  png.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
  const int channels = static_cast<int>(PNG_IMAGE_SAMPLE_CHANNELS(png.format));
  const bool has_alpha = (png.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  std::vector<png_byte> buffer(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, buffer.data(), 0, nullptr)) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw InputError(path + ": cannot read PNG: " + reason);
  }
  const int colours = has_alpha ? channels - 1 : channels;  // Alpha comes last.
  const bool averaged = has_alpha && alpha == ImageAlpha::kAveraged;
  GrayImage image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.max_value = 255u * static_cast<std::uint32_t>(averaged ? channels : colours);
  image.pixels.resize(n);
  if (has_alpha && !averaged) image.transparent.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const png_byte* pixel = buffer.data() + i * channels;
    std::uint32_t sum = 0;
    for (int c = 0; c < colours; ++c) sum += pixel[c];
    if (averaged) sum += pixel[colours];
    image.pixels[i] = sum;
    if (!image.transparent.empty()) image.transparent[i] = pixel[colours] != 255;
  }
  return image;
}

}  // namespace

GrayImage ReadGrayImage(const std::string& path, ImageAlpha alpha) {
  const std::string bytes = ReadFile(path);  // Read once, whichever format it holds.
  static const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPngSignature, 8) == 0) {
    return PngFromBytes(path, bytes, alpha);
  }
  return PgmFromBytes(path, bytes);
}

}  // namespace acdplan::envs::internal
