#pragma once
// ROS map_server occupancy maps: map.yaml plus a PGM or PNG image.

#include <string>
#include <vector>

#include "envs/occupancy_grid.h"
#include "envs/workspace2d.h"

namespace acdplan::envs {

/// How ReadOccupancyMap() treats cells that are neither occupied nor free.
enum class UnknownCells {
  kBlocked,  ///< Conservative: unknown space is an obstacle (default).
  kFree,     ///< Optimistic: unknown space is free.
};

/// "blocked" or "free" (as ROS planners' allow_unknown chooses), for command lines and files.
/// @throws InputError "unknown unknown-cells rule 'x' (expected one of: blocked, free)".
UnknownCells ParseUnknownCells(const std::string& name);

/// Options for ReadOccupancyMap(); `{}` is valid.
struct OccupancyMapOptions {
  UnknownCells unknown =
      UnknownCells::kBlocked;  ///< Cells between free_thresh and occupied_thresh.
  /// If given, receives one line, naming the file, per thing read but left out (a yaw).
  std::vector<std::string>* notes = nullptr;
};

/// Reads a ROS map_server `map.yaml`:
///   image: path of a PGM (P2 or P5, any maxval) or PNG image, relative to the YAML's folder
///   resolution: metres per pixel (> 0)
///   origin: [x, y, yaw] of the lower-left pixel's corner; a yaw other than 0 is left out with
///     a note: the map is read unrotated, as ROS's navigation stack reads it (map_server's
///     documentation: "many parts of the system currently ignore yaw"; costmap_2d and AMCL
///     do), so that coordinates agree with what a robot on that stack uses
///   occupied_thresh, free_thresh: in [0, 1], free_thresh < occupied_thresh (free_thresh
///     defaults to 0.196 and occupied_thresh to 0.65 when absent)
///   negate: 0 or 1, or a YAML boolean (default 0)
///   mode: trinary (default), scale or raw, as map_server reads them (below)
/// A pixel's grey level v (of m, white) is the mean of its channels: grey, or red, green and
/// blue (not a luminance), and in trinary mode alpha as one more channel
/// (envs/internal/gray_image.h). Its occupancy is p = (m - v) / m, or v / m when negate is 1;
/// in raw mode p = v / 100 with v scaled to 0..255 (the image holds percentages), unknown above
/// 100, negate left out (Nav2's rule); in scale mode a pixel that is not fully opaque is unknown.
/// p > occupied_thresh is blocked, p < free_thresh is free, anything else unknown (blocked or
/// free by OccupancyMapOptions::unknown). (Raw mode applies the thresholds to the percentages:
/// map_server passes them on as they are, and a binary world needs a cut somewhere.)
/// @throws InputError naming the file, the key and the rule, e.g.
///   "map.yaml: resolution: expected a number > 0", "map.yaml: image: cannot read
///   'missing.pgm': No such file or directory", "map.pgm: malformed PGM header".
OccupancyGrid ReadOccupancyMap(const std::string& yaml_path,
                               const OccupancyMapOptions& options = {});

/// GridWorkspace(ReadOccupancyMap(yaml_path, options)).
Workspace2d LoadOccupancyMap(const std::string& yaml_path, const OccupancyMapOptions& options = {});

}  // namespace acdplan::envs
