#include "envs/world_svg.h"

#include <algorithm>

#include "acd/svg_style.h"

namespace acdplan::envs {
namespace {

constexpr double kPicturePixels = 800.0;
constexpr double kMarginPixels = 10.0;
constexpr double kCaptionPixels = 24.0;

std::string Number(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}

}  // namespace

WorldSvg::WorldSvg(const Eigen::AlignedBox2d& bounds) : bounds_(bounds) {
  const double size = bounds.sizes().maxCoeff();
  scale_ = size > 0.0 ? kPicturePixels / size : 1.0;
  const Eigen::Vector2d sizes = bounds.sizes() * scale_;
  body_ << "<rect x=\"" << X(bounds.min().x()) << "\" y=\"" << Y(bounds.max().y())
        << "\" width=\"" << Number(sizes.x()) << "\" height=\"" << Number(sizes.y())
        << "\" fill=\"white\" stroke=\"black\"/>\n";
}

std::string WorldSvg::X(double x) const {
  return Number(kMarginPixels + (x - bounds_.min().x()) * scale_);
}

std::string WorldSvg::Y(double y) const {
  return Number(kMarginPixels + (bounds_.max().y() - y) * scale_);
}

std::string WorldSvg::Point(const Eigen::Vector2d& p) const { return X(p.x()) + "," + Y(p.y()); }

std::string WorldSvg::PathData(const acd::Polygon2d& polygon) const {
  std::string d;
  auto ring = [&](const acd::Ring2d& r) {
    d += "M";
    for (const acd::Point2d& p : r) d += Point(p) + " ";
    d += "Z ";
  };
  ring(polygon.outer);
  for (const acd::Ring2d& hole : polygon.holes) ring(hole);
  return d;
}

void WorldSvg::AddComponents(const acd::Decomposition2d& decomposition, bool distinct) {
  body_ << "<g id=\"components\" fill=\"#cfe3f7\" fill-opacity=\"0.6\" stroke=\"#5b7394\" "
           "stroke-width=\"0.8\" fill-rule=\"evenodd\">\n";
  for (size_t k = 0; k < decomposition.components.size(); ++k) {
    body_ << "<path";
    if (distinct) body_ << " fill=\"" << acd::ComponentFill(static_cast<int>(k)) << "\"";
    body_ << " d=\"" << PathData(decomposition.components[k].polygon) << "\"/>\n";
  }
  body_ << "</g>\n";
}

void WorldSvg::AddObstacles(const std::vector<acd::Polygon2d>& obstacles) {
  body_ << "<g id=\"obstacles\" fill=\"#555\" fill-rule=\"evenodd\">\n";
  for (const acd::Polygon2d& obstacle : obstacles) {
    body_ << "<path d=\"" << PathData(obstacle) << "\"/>\n";
  }
  body_ << "</g>\n";
}

void WorldSvg::AddOpenings(const acd::Decomposition2d& decomposition) {
  body_ << "<g id=\"openings\" stroke=\"#f08c00\" stroke-width=\"3\" stroke-linecap=\"round\">\n";
  for (const acd::Opening2d& o : decomposition.openings) {
    body_ << "<line x1=\"" << X(o.a.x()) << "\" y1=\"" << Y(o.a.y()) << "\" x2=\"" << X(o.b.x())
          << "\" y2=\"" << Y(o.b.y()) << "\"/>\n";
  }
  body_ << "</g>\n";
}

void WorldSvg::Add(const std::string& elements) { body_ << elements; }

std::string WorldSvg::Finish(const std::string& caption) const {
  const Eigen::Vector2d sizes = bounds_.sizes() * scale_;
  const double width = sizes.x() + 2 * kMarginPixels;
  const double height = sizes.y() + 2 * kMarginPixels + kCaptionPixels;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Number(width) << "\" height=\""
      << Number(height) << "\" viewBox=\"0 0 " << Number(width) << " " << Number(height)
      << "\">\n"
      << body_.str() << "<text x=\"" << Number(kMarginPixels) << "\" y=\""
      << Number(height - 8) << "\" font-family=\"sans-serif\" font-size=\"14\">"
      << acd::EscapeXml(caption) << "</text>\n</svg>\n";
  return svg.str();
}

std::string WorldToSvg(const Workspace2d& workspace, const acd::Decomposition2d& free_space,
                       const std::string& caption) {
  WorldSvg svg(workspace.bounds);
  svg.AddComponents(free_space, /*distinct=*/true);
  svg.AddObstacles(workspace.obstacles);
  svg.AddOpenings(free_space);
  return svg.Finish(caption);
}

}  // namespace acdplan::envs
