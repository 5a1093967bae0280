#include "envs/occupancy_map.h"

#include <cmath>
#include <sstream>

#include "base/enum_names.h"
#include "base/file_io.h"
#include "base/input_error.h"
#include "base/yaml_file.h"
#include "envs/internal/gray_image.h"

namespace acdplan::envs {

UnknownCells ParseUnknownCells(const std::string& name) {
  static constexpr std::array<EnumName<UnknownCells>, 2> kRules = {{
      {UnknownCells::kBlocked, "blocked"},
      {UnknownCells::kFree, "free"},
  }};
  return ValueOf(kRules, name, "unknown-cells rule");
}

OccupancyGrid ReadOccupancyMap(const std::string& yaml_path, const OccupancyMapOptions& options) {
  const YamlFile file = YamlFile::Load(yaml_path);
  const YAML::Node& root = file.root();
  file.CheckKeys(
      root, "",
      {"image", "resolution", "origin", "occupied_thresh", "free_thresh", "negate", "mode"});
  for (const char* key : {"image", "resolution", "origin"}) {
    if (!root[key]) file.Fail(key, "missing required key");
  }
  const std::string image_name = file.String(root["image"], "image");
  const double resolution = file.Number(root["resolution"], "resolution");
  if (!(resolution > 0.0)) file.Fail("resolution", "expected a number > 0");
  const std::vector<double> origin = file.Numbers(root["origin"], "origin", 3, "[x, y, yaw]");
  if (origin[2] != 0.0 && options.notes != nullptr) {
    std::ostringstream note;
    note << yaml_path << ": origin: yaw " << origin[2]
         << " left out: the map is read unrotated, as ROS's navigation stack reads it";
    options.notes->push_back(note.str());
  }
  const double occupied_thresh =
      root["occupied_thresh"] ? file.Number(root["occupied_thresh"], "occupied_thresh") : 0.65;
  const double free_thresh =
      root["free_thresh"] ? file.Number(root["free_thresh"], "free_thresh") : 0.196;
  if (occupied_thresh < 0.0 || occupied_thresh > 1.0) {
    file.Fail("occupied_thresh", "expected a number in [0, 1]");
  }
  if (free_thresh < 0.0 || free_thresh > 1.0)
    file.Fail("free_thresh", "expected a number in [0, 1]");
  if (!(free_thresh < occupied_thresh)) {
    file.Fail("free_thresh", "must be less than occupied_thresh");
  }
  bool negate = false;
  if (const YAML::Node node = root["negate"]) {
    // map_server writes 0 / 1; YAML booleans are accepted too.
    bool flag = false;
    if (node.IsScalar() && YAML::convert<bool>::decode(node, flag)) {
      negate = flag;
    } else {
      const double value = file.Number(node, "negate");
      if (value != 0.0 && value != 1.0) file.Fail("negate", "expected 0 or 1");
      negate = value == 1.0;
    }
  }
  enum class Mode { kTrinary, kScale, kRaw };
  Mode mode = Mode::kTrinary;
  if (root["mode"]) {
    const std::string name = file.String(root["mode"], "mode");
    if (name == "scale") {
      mode = Mode::kScale;
    } else if (name == "raw") {
      mode = Mode::kRaw;
    } else if (name != "trinary") {
      file.Fail("mode", "expected trinary, scale or raw, got '" + name + "'");
    }
  }

  const std::string image_path = file.ResolvePath(image_name);
  if (const std::string reason = UnreadableFileReason(image_path); !reason.empty()) {
    file.Fail("image", image_path + ": cannot read the file: " + reason);
  }
  const internal::GrayImage image =
      internal::ReadGrayImage(image_path, mode == Mode::kTrinary ? internal::ImageAlpha::kAveraged
                                                                 : internal::ImageAlpha::kSeparate);

  OccupancyGrid grid;
  grid.width = image.width;
  grid.height = image.height;
  grid.resolution = resolution;
  grid.origin = Eigen::Vector2d(origin[0], origin[1]);
  grid.blocked.resize(image.pixels.size());
  const double max_value = image.max_value;
  const bool unknown_blocked = options.unknown == UnknownCells::kBlocked;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const double value = image.pixels[i];  // 0 black, max_value white.
    // The occupancy in [0, 1], or NaN for unknown by the mode's own rule.
    double occupancy;
    if (mode == Mode::kRaw) {
      // The grey level (of 255) is the occupancy in percent; above 100, unknown. Nav2's rule,
      // which leaves `negate` out (ROS 1's map_server applied it first).
      const double percent = std::round(value * 255.0 / max_value);
      occupancy = percent <= 100.0 ? percent / 100.0 : std::nan("");
    } else if (!image.transparent.empty() && image.transparent[i]) {
      occupancy = std::nan("");  // Scale mode: a pixel not fully opaque is unknown.
    } else {
      occupancy = negate ? value / max_value : (max_value - value) / max_value;
    }
    bool blocked;
    if (occupancy > occupied_thresh) {
      blocked = true;
    } else if (occupancy < free_thresh) {
      blocked = false;
    } else {
      blocked = unknown_blocked;  // Between the thresholds, or unknown (NaN).
    }
    grid.blocked[i] = blocked ? 1 : 0;
  }
  return grid;
}

Workspace2d LoadOccupancyMap(const std::string& yaml_path, const OccupancyMapOptions& options) {
  Workspace2d workspace = GridWorkspace(ReadOccupancyMap(yaml_path, options));
  workspace.description = "occupancy map " + yaml_path;
  return workspace;
}

}  // namespace acdplan::envs
