// libFuzzer target: envs::internal::ReadGrayImage() on arbitrary bytes written to a file, with
// alpha averaged and separate; what it returns must hold its contract (grey levels within
// max_value, a transparency flag per pixel or none).
// InputError is the expected answer to bad input; anything else (another exception, a crash, a
// sanitizer report, a hang) is a finding.
#include <cstdlib>

#include "base/input_error.h"
#include "envs/internal/gray_image.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using acdplan::envs::internal::ImageAlpha;
  const std::string path =
      acdplan::fuzz::WriteInputFile("fuzz.img", acdplan::fuzz::InputText(data, size));
  for (const ImageAlpha alpha : {ImageAlpha::kAveraged, ImageAlpha::kSeparate}) {
    try {
      const acdplan::envs::internal::GrayImage image =
          acdplan::envs::internal::ReadGrayImage(path, alpha);
      const size_t n = static_cast<size_t>(image.width) * image.height;
      if (image.pixels.size() != n || image.max_value == 0) std::abort();
      if (!image.transparent.empty() &&
          (alpha == ImageAlpha::kAveraged || image.transparent.size() != n)) {
        std::abort();
      }
      for (const std::uint32_t v : image.pixels) {
        if (v > image.max_value) std::abort();
      }
    } catch (const acdplan::InputError&) {
    }
  }
  return 0;
}
