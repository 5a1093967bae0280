#pragma once
// Writing SVG pictures of 2D drawings: one canvas that maps world coordinates to the picture,
// the component colours and text escaping every acdplan picture shares.

#include <Eigen/Geometry>
#include <sstream>
#include <string>
#include <vector>

namespace acdplan {

/// The k-th component's fill colour ("#rrggbb"): hues stepped by the golden ratio, so
/// neighbours in the depth-first component order (often geometric neighbours too) get well
/// separated hues.
std::string ComponentFill(int k);

/// `text` with the XML special characters escaped and control characters dropped.
std::string EscapeXml(const std::string& text);

/// Options for SvgCanvas; `{}` is valid.
struct SvgCanvasOptions {
  double pixels = 800.0;  ///< Size of the drawing's longer side [px]; > 0.
  double margin = 10.0;   ///< Around the drawing [px]; >= 0.
  double font = 14.0;     ///< Caption font size [px]; > 0.
};

/// A picture of a drawing given in world coordinates (y up). World points map to picture
/// pixels (y down) by a translation and one scale, so the drawing's longer side is
/// `options.pixels` wide whatever its units; the caption lines go below the drawing, and the
/// picture widens when a caption line is wider than the drawing. Elements are painted in the
/// order they are added.
class SvgCanvas {
 public:
  explicit SvgCanvas(const Eigen::AlignedBox2d& bounds, const SvgCanvasOptions& options = {});

  /// Picture coordinates of world x, y, and of a point as "x,y".
  std::string X(double x) const;
  std::string Y(double y) const;
  std::string Point(const Eigen::Vector2d& p) const;
  /// Path data of closed rings ("M x,y L x,y ... Z"); with fill-rule="evenodd" the rings after
  /// the first are holes.
  std::string PathData(const std::vector<std::vector<Eigen::Vector2d>>& rings) const;
  /// Pixels per world unit.
  double scale() const { return scale_; }

  /// Any SVG element(s), in picture coordinates.
  void Add(const std::string& elements) { body_ << elements; }

  /// The finished document: a <title> of `title` (if not empty), a white background, the
  /// elements, and `caption` (one <text> per line, escaped) under the drawing.
  std::string Finish(const std::vector<std::string>& caption, const std::string& title = "") const;

  /// A number in picture units, short ("%.6g").
  static std::string Number(double pixels);

 private:
  Eigen::AlignedBox2d bounds_;
  SvgCanvasOptions options_;
  double scale_ = 1.0;
  std::ostringstream body_;
};

}  // namespace acdplan
