#pragma once
// What every acdplan SVG shares: the component fills and text escaping.

#include <string>

namespace acdplan::acd {

/// The k-th component's fill colour ("#rrggbb"): hues stepped by the golden ratio, so
/// neighbours in the depth-first component order (often geometric neighbours too) get well
/// separated hues.
std::string ComponentFill(int k);

/// `text` with the XML special characters escaped and control characters dropped.
std::string EscapeXml(const std::string& text);

}  // namespace acdplan::acd
