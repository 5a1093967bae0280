#pragma once
// Where the tests find the repository's data and configuration files.

#include <filesystem>
#include <string>

namespace acdplan::test {

/// data/polygons/acd2d: the polygons of Lien's ACD code.
inline const std::filesystem::path kAcd2d =
    std::filesystem::path(ACDPLAN_DATA_DIR) / "polygons" / "acd2d";
/// configs/ (scenarios, benchmark specifications), without a trailing slash.
inline const std::string kConfigs = std::string(ACDPLAN_SOURCE_DIR) + "/configs";

}  // namespace acdplan::test
