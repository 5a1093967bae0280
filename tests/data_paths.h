#pragma once
// Where the tests find the repository's data and configuration files and the acdplan binary.

#include <filesystem>
#include <string>

namespace acdplan::test {

/// The repository's root folder (this checkout). Defined in a file tests/CMakeLists.txt
/// generates, so that no compiled test unit names the checkout's folder.
std::string SourceDir();
/// The repository's data/ folder.
inline std::string DataDir() { return SourceDir() + "/data"; }
/// The built `acdplan` command line; empty in a build without tools (ACDPLAN_BUILD_TOOLS=OFF).
std::string AcdplanBinary();

/// data/polygons/acd2d: the polygons of Lien's ACD code.
inline const std::filesystem::path kAcd2d = std::filesystem::path(DataDir()) / "polygons" / "acd2d";
/// data/polygons/shapefiles: ESRI shapefiles (.shp with their .dbf) written by other software.
inline const std::filesystem::path kShapefiles =
    std::filesystem::path(DataDir()) / "polygons" / "shapefiles";
/// data/polygons/geopackage: GeoPackages written by other software.
inline const std::filesystem::path kGeoPackages =
    std::filesystem::path(DataDir()) / "polygons" / "geopackage";
/// configs/ (scenarios, benchmark specifications), without a trailing slash.
inline const std::string kConfigs = SourceDir() + "/configs";

}  // namespace acdplan::test
