#include "envs/world_svg.h"

#include <sstream>

namespace acdplan::envs {

WorldSvg::WorldSvg(const Eigen::AlignedBox2d& bounds) : canvas_(bounds) {
  const Eigen::Vector2d sizes = bounds.sizes() * canvas_.scale();
  canvas_.Add("<rect x=\"" + X(bounds.min().x()) + "\" y=\"" + Y(bounds.max().y()) + "\" width=\"" +
              SvgCanvas::Number(sizes.x()) + "\" height=\"" + SvgCanvas::Number(sizes.y()) +
              "\" fill=\"white\" stroke=\"black\"/>\n");
}

std::string WorldSvg::PathData(const acd::Polygon2d& polygon) const {
  std::vector<acd::Ring2d> rings{polygon.outer};
  rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  return canvas_.PathData(rings);
}

void WorldSvg::AddComponents(const acd::Decomposition2d& decomposition, bool distinct) {
  std::ostringstream svg;
  svg << "<g id=\"components\" fill=\"#cfe3f7\" fill-opacity=\"0.6\" stroke=\"#5b7394\" "
         "stroke-width=\"0.8\" fill-rule=\"evenodd\">\n";
  for (size_t k = 0; k < decomposition.components.size(); ++k) {
    svg << "<path";
    if (distinct) svg << " fill=\"" << ComponentFill(static_cast<int>(k)) << "\"";
    svg << " d=\"" << PathData(decomposition.components[k].polygon) << "\"/>\n";
  }
  svg << "</g>\n";
  Add(svg.str());
}

void WorldSvg::AddObstacles(const std::vector<acd::Polygon2d>& obstacles) {
  std::ostringstream svg;
  svg << "<g id=\"obstacles\" fill=\"#555\" fill-rule=\"evenodd\">\n";
  for (const acd::Polygon2d& obstacle : obstacles) {
    svg << "<path d=\"" << PathData(obstacle) << "\"/>\n";
  }
  svg << "</g>\n";
  Add(svg.str());
}

void WorldSvg::AddOpenings(const acd::Decomposition2d& decomposition) {
  std::ostringstream svg;
  svg << "<g id=\"openings\" stroke=\"#f08c00\" stroke-width=\"3\" stroke-linecap=\"round\">\n";
  for (const acd::Opening2d& o : decomposition.openings) {
    svg << "<line x1=\"" << X(o.a.x()) << "\" y1=\"" << Y(o.a.y()) << "\" x2=\"" << X(o.b.x())
        << "\" y2=\"" << Y(o.b.y()) << "\"/>\n";
  }
  svg << "</g>\n";
  Add(svg.str());
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
