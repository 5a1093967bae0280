#include "acd/svg_style.h"

#include <cmath>
#include <cstdio>

namespace acdplan::acd {

std::string EscapeXml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // Control characters are not allowed in XML 1.0 text.
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n') out += c;
    }
  }
  return out;
}

std::string ComponentFill(int k) {
  constexpr double kGoldenRatioConjugate = 0.618033988749894848;
  const double hue = std::fmod(0.1 + k * kGoldenRatioConjugate, 1.0) * 6.0;  // [0, 6)
  const double saturation = 0.65, lightness = 0.58;
  // HSL -> RGB, written out as hex so every renderer accepts it.
  const double chroma = (1.0 - std::fabs(2.0 * lightness - 1.0)) * saturation;
  const double x = chroma * (1.0 - std::fabs(std::fmod(hue, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0:
      r = chroma;
      g = x;
      break;
    case 1:
      r = x;
      g = chroma;
      break;
    case 2:
      g = chroma;
      b = x;
      break;
    case 3:
      g = x;
      b = chroma;
      break;
    case 4:
      r = x;
      b = chroma;
      break;
    default:
      r = chroma;
      b = x;
      break;
  }
  const double m = lightness - chroma / 2.0;
  char buffer[8];
  auto channel = [m](double c) { return static_cast<int>(std::lround((c + m) * 255.0)); };
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", channel(r), channel(g), channel(b));
  return buffer;
}

}  // namespace acdplan::acd
