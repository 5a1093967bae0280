#include "base/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/format.h"

namespace acdplan {

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

SvgCanvas::SvgCanvas(const Eigen::AlignedBox2d& bounds, const SvgCanvasOptions& options)
    : bounds_(bounds), options_(options) {
  if (bounds_.isEmpty())
    bounds_ = Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero());
  const double size = bounds_.sizes().maxCoeff();
  scale_ = size > 0.0 ? options_.pixels / size : 1.0;
}

std::string SvgCanvas::Number(double pixels) { return FormatSignificant(pixels, 6); }

std::string SvgCanvas::X(double x) const {
  return Number(options_.margin + (x - bounds_.min().x()) * scale_);
}

std::string SvgCanvas::Y(double y) const {
  return Number(options_.margin + (bounds_.max().y() - y) * scale_);
}

std::string SvgCanvas::Point(const Eigen::Vector2d& p) const { return X(p.x()) + "," + Y(p.y()); }

std::string SvgCanvas::PathData(const std::vector<std::vector<Eigen::Vector2d>>& rings) const {
  std::string d;
  for (const std::vector<Eigen::Vector2d>& ring : rings) {
    for (size_t i = 0; i < ring.size(); ++i) d += (i == 0 ? "M" : "L") + Point(ring[i]) + " ";
    if (!ring.empty()) d += "Z ";
  }
  if (!d.empty()) d.pop_back();
  return d;
}

std::string SvgCanvas::Finish(const std::vector<std::string>& caption,
                              const std::string& title) const {
  const Eigen::Vector2d drawing = bounds_.sizes() * scale_;
  const double margin = options_.margin, font = options_.font, line_height = 1.35 * font;
  // A rough text width (0.55 em per character) is enough to keep the caption inside.
  size_t longest = 0;
  for (const std::string& line : caption) longest = std::max(longest, line.size());
  const double caption_width = 0.55 * font * static_cast<double>(longest);
  const double width = std::max(drawing.x(), caption_width) + 2 * margin;
  const double height = drawing.y() + 2 * margin + line_height * caption.size() +
                        (caption.empty() ? 0.0 : margin / 2);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Number(width) << "\" height=\""
      << Number(height) << "\" viewBox=\"0 0 " << Number(width) << " " << Number(height) << "\">\n";
  if (!title.empty()) svg << "<title>" << EscapeXml(title) << "</title>\n";
  svg << "<rect width=\"" << Number(width) << "\" height=\"" << Number(height)
      << "\" fill=\"#ffffff\"/>\n"
      << body_.str();
  if (!caption.empty()) {
    svg << "<g id=\"caption\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\""
        << Number(font) << "\" fill=\"#111111\">\n";
    for (size_t i = 0; i < caption.size(); ++i) {
      svg << "<text x=\"" << Number(margin) << "\" y=\""
          << Number(drawing.y() + 2 * margin + line_height * (i + 0.75)) << "\">"
          << EscapeXml(caption[i]) << "</text>\n";
    }
    svg << "</g>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace acdplan
