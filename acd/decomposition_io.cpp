#include "acd/decomposition_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <stdexcept>

#include "acd/svg_style.h"

namespace acdplan::acd {
namespace {

// ordered_json keeps the keys in DESIGN.md's order, so the file reads like the contract.
using Json = nlohmann::ordered_json;

Json PointToJson(const Point2d& p) { return Json::array({p.x(), p.y()}); }

Json RingToJson(const Ring2d& ring) {
  Json array = Json::array();
  for (const Point2d& p : ring) array.push_back(PointToJson(p));
  return array;
}

// ---------------------------------------------------------------------------------------------
// SVG helpers.

/// Axis-aligned bounds of the drawing in input coordinates.
struct Bounds {
  double min_x = std::numeric_limits<double>::infinity();
  double min_y = std::numeric_limits<double>::infinity();
  double max_x = -std::numeric_limits<double>::infinity();
  double max_y = -std::numeric_limits<double>::infinity();
  void Add(const Point2d& p) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
    min_x = std::min(min_x, p.x());
    min_y = std::min(min_y, p.y());
    max_x = std::max(max_x, p.x());
    max_y = std::max(max_y, p.y());
  }
  bool empty() const { return !(min_x <= max_x); }
};

/// A number for SVG text: 10 significant digits are plenty once the drawing is translated to
/// the origin (see SvgWriter::X/Y), and keep the file small.
std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

/// A number for the caption: short.
std::string Short(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

class SvgWriter {
 public:
  explicit SvgWriter(const Bounds& bounds) : bounds_(bounds) {}

  /// Input x, y to SVG coordinates: translated to the origin (so 10 digits keep the precision
  /// far from the origin too) and y flipped, since SVG's y axis points down.
  double X(double x) const { return x - bounds_.min_x; }
  double Y(double y) const { return bounds_.max_y - y; }

  std::string PathData(const Polygon2d& polygon) const {
    std::string d;
    auto ring = [&](const Ring2d& r) {
      for (size_t i = 0; i < r.size(); ++i) {
        d += (i == 0 ? "M" : "L") + Num(X(r[i].x())) + "," + Num(Y(r[i].y())) + " ";
      }
      if (!r.empty()) d += "Z ";
    };
    ring(polygon.outer);
    for (const Ring2d& hole : polygon.holes) ring(hole);
    if (!d.empty()) d.pop_back();
    return d;
  }

 private:
  Bounds bounds_;
};

}  // namespace

std::string DecompositionToJson(const Decomposition2d& decomposition,
                                const DecompositionLabels& labels) {
  Json json;
  json["format"] = "acdplan.decomposition2d/1";
  json["input"] = labels.input;
  json["measure"] = ToString(decomposition.measure);
  json["tau"] = decomposition.tau;
  json["tau_rel"] = labels.tau_rel >= 0 ? Json(labels.tau_rel) : Json(nullptr);

  Json components = Json::array();
  for (const Component2d& component : decomposition.components) {
    Json c;
    c["boundary"] = RingToJson(component.polygon.outer);
    Json holes = Json::array();
    for (const Ring2d& hole : component.polygon.holes) holes.push_back(RingToJson(hole));
    c["holes"] = std::move(holes);
    c["hull"] = RingToJson(component.hull);
    c["centroid"] = PointToJson(component.centroid);
    c["concavity"] = component.concavity;
    c["source"] = component.source;  // Extension: index of the input polygon.
    components.push_back(std::move(c));
  }
  json["components"] = std::move(components);

  Json openings = Json::array();
  for (const Opening2d& opening : decomposition.openings) {
    Json o;
    o["a"] = PointToJson(opening.a);
    o["b"] = PointToJson(opening.b);
    o["components"] = Json::array({opening.component_a, opening.component_b});
    openings.push_back(std::move(o));
  }
  json["openings"] = std::move(openings);

  const DecompositionStats2d& stats = decomposition.stats;
  json["stats"] = {{"vertices", stats.vertices},     {"notches", stats.notches},
                   {"components", stats.components}, {"max_concavity", stats.max_concavity},
                   {"convexity", stats.convexity},   {"time_ms", stats.time_ms}};

  // Extensions (DESIGN.md: extend, never change).
  if (decomposition.min_convexity > 0) json["min_convexity"] = decomposition.min_convexity;
  json["graph"] = ComponentGraph(decomposition);

  // nlohmann writes doubles with the shortest text that reads back to the same value.
  return json.dump() + "\n";
}

std::string DecompositionToSvg(const Decomposition2d& decomposition,
                               const DecompositionLabels& labels) {
  Bounds bounds;
  for (const Component2d& component : decomposition.components) {
    for (const Point2d& p : component.polygon.outer) bounds.Add(p);
  }
  if (bounds.empty()) {
    for (int root : decomposition.roots) {
      if (root < 0 || root >= static_cast<int>(decomposition.tree.size())) continue;
      for (const Point2d& p : decomposition.tree[root].piece.outer) bounds.Add(p);
    }
  }
  if (bounds.empty()) bounds.Add(Point2d::Zero());
  const SvgWriter writer(bounds);

  const double width = bounds.max_x - bounds.min_x;
  const double height = bounds.max_y - bounds.min_y;
  double size = std::max(width, height);
  if (!(size > 0)) size = 1.0;
  // Every length below is relative to the drawing's size, so the picture looks the same for a
  // polygon measured in millimetres or in kilometres.
  const double margin = 0.04 * size;
  const double thin = 0.0015 * size;
  const double opening_width = 0.006 * size;
  const double notch_radius = 0.006 * size;
  const double root_radius = 0.016 * size;
  const double font = 0.026 * size;

  // The caption.
  std::vector<std::string> caption;
  caption.push_back(labels.input.empty() ? std::string("(unnamed input)") : labels.input);
  std::string line = "tau " + Short(decomposition.tau);
  if (labels.tau_rel >= 0) line += " (tau_rel " + Short(labels.tau_rel) + ")";
  if (decomposition.min_convexity > 0) {
    line += ", min convexity " + Short(decomposition.min_convexity);
  }
  line += ", measure " + ToString(decomposition.measure) + ", " +
          std::to_string(decomposition.components.size()) + " components, convexity " +
          Short(decomposition.stats.convexity) + ", " + Short(decomposition.stats.time_ms) + " ms";
  caption.push_back(line);
  caption.push_back(
      "red rings: most concave notches of the input; dots: resolved notches (where cuts "
      "start); orange: openings");

  // The view box: the drawing plus a margin, widened when the caption needs more room (a
  // tall, narrow polygon), with the caption below.
  size_t longest = 0;
  for (const std::string& text : caption) longest = std::max(longest, text.size());
  const double caption_width = 0.55 * font * static_cast<double>(longest);
  const double view_width = std::max(width + 2 * margin, caption_width + 2 * margin);
  const double view_x = -margin - (view_width - (width + 2 * margin)) / 2.0;
  const double line_height = 1.35 * font;
  const double caption_top = height + margin;
  const double view_height = height + 2 * margin + line_height * caption.size() + margin;
  const double pixels = 900.0;
  const double pixel_width = view_width >= view_height ? pixels : pixels * view_width / view_height;
  const double pixel_height =
      view_width >= view_height ? pixels * view_height / view_width : pixels;

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << Num(pixel_width)
      << "\" height=\"" << Num(pixel_height) << "\" viewBox=\"" << Num(view_x) << " "
      << Num(-margin) << " " << Num(view_width) << " " << Num(view_height) << "\">\n";
  svg << "<title>" << EscapeXml(caption[0] + ": " + caption[1]) << "</title>\n";
  svg << "<rect x=\"" << Num(view_x) << "\" y=\"" << Num(-margin) << "\" width=\""
      << Num(view_width) << "\" height=\"" << Num(view_height) << "\" fill=\"#ffffff\"/>\n";

  // Components: filled, semi-transparent, thin dark boundaries; even-odd fill leaves the
  // unresolved holes open.
  svg << "<g id=\"components\" stroke=\"#222222\" stroke-width=\"" << Num(thin)
      << "\" stroke-linejoin=\"round\" fill-opacity=\"0.6\" fill-rule=\"evenodd\">\n";
  for (size_t k = 0; k < decomposition.components.size(); ++k) {
    const Component2d& component = decomposition.components[k];
    svg << "<path class=\"component\" fill=\"" << ComponentFill(static_cast<int>(k)) << "\" d=\""
        << writer.PathData(component.polygon) << "\"><title>component " << k << ": concavity "
        << Short(component.concavity) << "</title></path>\n";
  }
  svg << "</g>\n";

  // Openings: the passages between components.
  svg << "<g id=\"openings\" stroke=\"#f07800\" stroke-width=\"" << Num(opening_width)
      << "\" stroke-linecap=\"round\">\n";
  for (const Opening2d& opening : decomposition.openings) {
    svg << "<line x1=\"" << Num(writer.X(opening.a.x())) << "\" y1=\""
        << Num(writer.Y(opening.a.y())) << "\" x2=\"" << Num(writer.X(opening.b.x())) << "\" y2=\""
        << Num(writer.Y(opening.b.y())) << "\"/>\n";
  }
  svg << "</g>\n";

  // Notches: every split node's witness is a resolved notch (a small dot); a root's witness
  // is the most concave point of its input polygon (a red ring). A leaf's witness means
  // nothing (HierarchyNode2d), so only split nodes are drawn.
  svg << "<g id=\"notches\">\n";
  const int node_count = static_cast<int>(decomposition.tree.size());
  for (const HierarchyNode2d& node : decomposition.tree) {
    if (node.children[0] < 0) continue;
    svg << "<circle class=\"resolved-notch\" cx=\"" << Num(writer.X(node.witness.x())) << "\" cy=\""
        << Num(writer.Y(node.witness.y())) << "\" r=\"" << Num(notch_radius)
        << "\" fill=\"#111111\"/>\n";
  }
  for (int root : decomposition.roots) {
    if (root < 0 || root >= node_count) continue;
    const HierarchyNode2d& node = decomposition.tree[root];
    if (node.children[0] < 0) continue;
    svg << "<circle class=\"most-concave-notch\" cx=\"" << Num(writer.X(node.witness.x()))
        << "\" cy=\"" << Num(writer.Y(node.witness.y())) << "\" r=\"" << Num(root_radius)
        << "\" fill=\"none\" stroke=\"#d01010\" stroke-width=\"" << Num(2.5 * thin)
        << "\"><title>most concave notch: concavity " << Short(node.concavity)
        << "</title></circle>\n";
  }
  svg << "</g>\n";

  // Caption at the bottom, in unflipped coordinates.
  svg << "<g id=\"caption\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"" << Num(font)
      << "\" fill=\"#111111\">\n";
  for (size_t i = 0; i < caption.size(); ++i) {
    svg << "<text x=\"" << Num(view_x + margin) << "\" y=\""
        << Num(caption_top + line_height * (i + 1)) << "\""
        << (i == 0 ? " font-weight=\"bold\"" : "") << ">" << EscapeXml(caption[i]) << "</text>\n";
  }
  svg << "</g>\n</svg>\n";
  return svg.str();
}

void WriteFileAtomically(const std::string& path, const std::string& text) {
  auto fail = [&path](const std::string& why) {
    throw std::runtime_error("cannot write '" + path + "': " + why);
  };
  namespace fs = std::filesystem;
  if (path.empty()) fail("empty file name");
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) fail("cannot create directory '" + parent.string() + "': " + ec.message());
  }

  // The temporary file sits in the same directory, so the rename is atomic (same file
  // system). O_EXCL with a random suffix instead of mkstemp(): the file gets the usual
  // 0666 & ~umask permissions rather than mkstemp's 0600.
  std::random_device entropy;
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, ".tmp-%06x", static_cast<unsigned>(entropy() & 0xffffff));
    temporary = path + suffix;
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail(std::strerror(errno));
  }
  if (fd < 0) fail("cannot create a temporary file");

  const char* data = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      ::unlink(temporary.c_str());
      fail(std::strerror(error));
    }
    data += written;
    left -= static_cast<size_t>(written);
  }
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail(std::strerror(error));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail(std::strerror(error));
  }
}

}  // namespace acdplan::acd
