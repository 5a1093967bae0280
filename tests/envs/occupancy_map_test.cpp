#include "envs/occupancy_map.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <png.h>

#include <cstring>

#include "envs/free_space2d.h"
#include "envs/load_workspace.h"
#include "test_util.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::TempDir;

// 4 x 3 pixels, row 0 on top: 0 = black (occupied), 254 = white (free), 205 = grey (unknown).
const std::vector<int> kPixels = {0, 254, 254, 205,  //
                                  0, 254, 254, 254,  //
                                  0, 0,   254, 254};

std::string PlainPgm() {
  std::string text = "P2\n# a comment\n4 3\n255\n";
  for (int v : kPixels) text += std::to_string(v) + " ";
  return text + "\n";
}

std::string BinaryPgm() {
  std::string text = "P5 4 3 255\n";
  for (int v : kPixels) text += static_cast<char>(v);
  return text;
}

// Writes `samples` (format's channels per pixel, row 0 on top) as an 8-bit PNG.
void WritePng(const std::string& path, png_uint_32 format, int width, int height,
              const std::vector<png_byte>& samples) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = format;
  ASSERT_EQ(samples.size(), PNG_IMAGE_SIZE(image));
  ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, samples.data(), 0, nullptr));
}

// kPixels as grey RGB pixels.
void WritePng(const std::string& path) {
  std::vector<png_byte> rgb;
  for (int v : kPixels) rgb.insert(rgb.end(), 3, static_cast<png_byte>(v));
  WritePng(path, PNG_FORMAT_RGB, 4, 3, rgb);
}

const char* kYaml =
    "image: map.pgm\nresolution: 0.5\norigin: [-1.0, 2.0, 0.0]\n"
    "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n";

const std::vector<std::uint8_t> kBlocked = {1, 0, 0, 1,  //
                                            1, 0, 0, 0,  //
                                            1, 1, 0, 0};

TEST(OccupancyMapTest, ReadsPlainAndBinaryPgmAndPng) {
  TempDir dir;
  for (const std::string format : {"P2", "P5", "PNG"}) {
    SCOPED_TRACE(format);
    std::string yaml = kYaml;
    if (format == "P2") dir.Write("map.pgm", PlainPgm());
    if (format == "P5") dir.Write("map.pgm", BinaryPgm());
    if (format == "PNG") {
      WritePng(dir.Path("map.png"));
      yaml.replace(yaml.find("map.pgm"), 7, "map.png");
    }
    const OccupancyGrid grid = ReadOccupancyMap(dir.Write("map.yaml", yaml));
    EXPECT_EQ(grid.width, 4);
    EXPECT_EQ(grid.height, 3);
    EXPECT_EQ(grid.blocked, kBlocked);
    EXPECT_EQ(grid.resolution, 0.5);
    EXPECT_EQ(grid.origin, Eigen::Vector2d(-1, 2));
  }
}

TEST(OccupancyMapTest, NegateAndUnknownCells) {
  TempDir dir;
  dir.Write("map.pgm", BinaryPgm());
  std::string yaml = kYaml;
  yaml.replace(yaml.find("negate: 0"), 9, "negate: 1");
  const OccupancyGrid negated = ReadOccupancyMap(dir.Write("map.yaml", yaml));
  // White is now occupied, black free; grey (205/255 = 0.80) is occupied too.
  EXPECT_EQ(negated.blocked, (std::vector<std::uint8_t>{0, 1, 1, 1, 0, 1, 1, 1, 0, 0, 1, 1}));
  yaml.replace(yaml.find("negate: 1"), 9, "negate: true");
  EXPECT_EQ(ReadOccupancyMap(dir.Write("map.yaml", yaml)).blocked, negated.blocked);
  const OccupancyGrid optimistic =
      ReadOccupancyMap(dir.Write("map.yaml", kYaml), {UnknownCells::kFree});
  EXPECT_EQ(optimistic.blocked[3], 0);
}

// map_server's grey level of a colour pixel is the mean of its channels, not a luminance:
// yellow (255, 255, 0) has mean 170, occupancy 0.33 (unknown), where its luminance (about 237)
// would make it free; green (0, 255, 0) has mean 85, occupancy 0.67 (occupied), where its
// luminance (about 182) would leave it unknown.
TEST(OccupancyMapTest, AColourPixelIsTheMeanOfItsChannels) {
  TempDir dir;
  WritePng(dir.Path("map.png"), PNG_FORMAT_RGB, 4, 1,
           {255, 255, 255, 255, 255, 0, 0, 255, 0, 0, 0, 0});
  std::string yaml = kYaml;
  yaml.replace(yaml.find("map.pgm"), 7, "map.png");
  const std::string path = dir.Write("map.yaml", yaml);
  EXPECT_EQ(ReadOccupancyMap(path).blocked, (std::vector<std::uint8_t>{0, 1, 1, 1}));
  EXPECT_EQ(ReadOccupancyMap(path, {UnknownCells::kFree}).blocked,
            (std::vector<std::uint8_t>{0, 0, 1, 1}));
}

// Alpha, by mode: trinary averages it in as a fourth channel (opaque = 255), scale makes every
// pixel that is not fully opaque unknown, raw leaves it out.
TEST(OccupancyMapTest, AlphaAsEachModeReadsIt) {
  TempDir dir;
  // White opaque, white transparent, black transparent, black opaque, white nearly opaque.
  WritePng(dir.Path("map.png"), PNG_FORMAT_RGBA, 5, 1,
           {255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0, 0, 0, 0, 0, 255, 255, 255, 255, 254});
  auto blocked = [&](const std::string& mode, UnknownCells unknown) {
    std::string yaml = kYaml;
    yaml.replace(yaml.find("map.pgm"), 7, "map.png");
    return ReadOccupancyMap(dir.Write("map.yaml", yaml + "mode: " + mode + "\n"), {unknown})
        .blocked;
  };
  using Cells = std::vector<std::uint8_t>;
  // Trinary: white transparent has mean 191.25, occupancy 0.25 (unknown); black transparent
  // mean 0 (occupied); nearly opaque white is free.
  EXPECT_EQ(blocked("trinary", UnknownCells::kBlocked), (Cells{0, 1, 1, 1, 0}));
  EXPECT_EQ(blocked("trinary", UnknownCells::kFree), (Cells{0, 0, 1, 1, 0}));
  EXPECT_EQ(blocked("scale", UnknownCells::kBlocked), (Cells{0, 1, 1, 1, 1}));
  EXPECT_EQ(blocked("scale", UnknownCells::kFree), (Cells{0, 0, 0, 1, 0}));
  // Raw: white (255 > 100) is unknown whatever its alpha, black is 0% occupied.
  EXPECT_EQ(blocked("raw", UnknownCells::kBlocked), (Cells{1, 1, 0, 0, 1}));
  EXPECT_EQ(blocked("raw", UnknownCells::kFree), (Cells{0, 0, 0, 0, 0}));
}

// Raw mode (map_saver's --mode raw): a pixel's value is its occupancy in percent, above 100
// unknown (map_saver writes unknown cells as 255); the thresholds apply to the percentages.
TEST(OccupancyMapTest, RawModeReadsPercentages) {
  TempDir dir;
  const std::vector<int> values = {0, 19, 20, 65, 66, 100, 101, 255};
  std::string pgm = "P2\n8 1\n255\n";
  for (int v : values) pgm += std::to_string(v) + " ";
  dir.Write("map.pgm", pgm);
  const std::string raw = std::string(kYaml) + "mode: raw\n";
  using Cells = std::vector<std::uint8_t>;
  // free_thresh 0.196, occupied_thresh 0.65.
  EXPECT_EQ(ReadOccupancyMap(dir.Write("map.yaml", raw)).blocked, (Cells{0, 0, 1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(ReadOccupancyMap(dir.Write("map.yaml", raw), {UnknownCells::kFree}).blocked,
            (Cells{0, 0, 0, 0, 1, 1, 0, 0}));
  // negate does not apply to percentages (Nav2's map_server).
  std::string negated = raw;
  negated.replace(negated.find("negate: 0"), 9, "negate: 1");
  EXPECT_EQ(ReadOccupancyMap(dir.Write("map.yaml", negated), {UnknownCells::kFree}).blocked,
            (Cells{0, 0, 0, 0, 1, 1, 0, 0}));
  // 16-bit samples scale to 0..255 first: 100 * 257 is 100%, 101 * 257 is unknown.
  dir.Write("map.pgm", "P2\n3 1\n65535\n0 25700 25957\n");
  EXPECT_EQ(ReadOccupancyMap(dir.Write("map.yaml", raw), {UnknownCells::kFree}).blocked,
            (Cells{0, 1, 0}));
}

TEST(OccupancyMapTest, UnknownCellsByNameAndThroughLoadWorld) {
  EXPECT_EQ(ParseUnknownCells("blocked"), UnknownCells::kBlocked);
  EXPECT_EQ(ParseUnknownCells("free"), UnknownCells::kFree);
  EXPECT_THAT(ErrorOf([] { ParseUnknownCells("Free"); }),
              HasSubstr("unknown unknown-cells rule 'Free' (expected one of: blocked, free)"));
  TempDir dir;
  dir.Write("map.pgm", PlainPgm());
  const std::string path = dir.Write("map.yaml", kYaml);
  // The unknown pixel is blocked by default: two obstacles; free, only the L of black pixels.
  EXPECT_EQ(LoadWorld(path).workspace2d.obstacles.size(), 2u);
  EXPECT_EQ(LoadWorld(path, {}, {UnknownCells::kFree}).workspace2d.obstacles.size(), 1u);
}

TEST(OccupancyMapTest, LoadsAWorkspaceInWorldCoordinates) {
  TempDir dir;
  dir.Write("map.pgm", PlainPgm());
  const Workspace2d world = LoadOccupancyMap(dir.Write("map.yaml", kYaml));
  EXPECT_EQ(world.bounds.min(), Eigen::Vector2d(-1, 2));
  EXPECT_EQ(world.bounds.max(), Eigen::Vector2d(1, 3.5));
  // The L of black pixels and the unknown pixel (blocked by default): two obstacles.
  ASSERT_EQ(world.obstacles.size(), 2u);
  EXPECT_EQ(world.obstacles[0].outer.size() + world.obstacles[1].outer.size(), 10u);
  const std::vector<acd::Polygon2d> free = FreeSpace2d(world);
  EXPECT_NEAR(testing::TotalArea(free), 7 * 0.25, 1e-9);
}

// A yaw is left out, as ROS's navigation stack leaves it out, with a note through LoadWorld().
TEST(OccupancyMapTest, AYawIsLeftOutWithANote) {
  TempDir dir;
  dir.Write("map.pgm", PlainPgm());
  std::string yaml = kYaml;
  yaml.replace(yaml.find("2.0, 0.0]"), 9, "2.0, 0.5]");
  const std::string path = dir.Write("map.yaml", yaml);
  std::vector<std::string> notes;
  OccupancyMapOptions options;
  options.notes = &notes;
  const OccupancyGrid grid = ReadOccupancyMap(path, options);
  EXPECT_EQ(grid.blocked, kBlocked);
  EXPECT_EQ(grid.origin, Eigen::Vector2d(-1, 2));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], path +
                          ": origin: yaw 0.5 left out: the map is read unrotated, as ROS's "
                          "navigation stack reads it");
  notes.clear();
  const World world = LoadWorld(path, {}, options);
  EXPECT_EQ(world.workspace2d.bounds.min(), Eigen::Vector2d(-1, 2));
  EXPECT_EQ(notes.size(), 1u);
  notes.clear();
  ReadOccupancyMap(dir.Write("map.yaml", kYaml), options);  // Yaw 0: nothing to say.
  EXPECT_TRUE(notes.empty());
}

TEST(OccupancyMapTest, YamlErrors) {
  TempDir dir;
  dir.Write("map.pgm", PlainPgm());
  auto error = [&](const std::string& yaml) {
    const std::string path = dir.Write("map.yaml", yaml);
    return ErrorOf([&] { ReadOccupancyMap(path); });
  };
  const std::string base = "image: map.pgm\nresolution: 0.5\norigin: [0, 0, 0]\n";
  EXPECT_THAT(error(base + "colour: red\n"),
              HasSubstr("map.yaml: colour: unknown key (expected one of: image, resolution, "
                        "origin, occupied_thresh, free_thresh, negate, mode)"));
  EXPECT_THAT(error("image: map.pgm\norigin: [0, 0, 0]\n"),
              HasSubstr("map.yaml: resolution: missing required key"));
  EXPECT_THAT(error("image: map.pgm\nresolution: -1\norigin: [0, 0, 0]\n"),
              HasSubstr("map.yaml: resolution: expected a number > 0"));
  EXPECT_THAT(error("image: map.pgm\nresolution: fine\norigin: [0, 0, 0]\n"),
              HasSubstr("map.yaml: resolution: expected a finite number"));
  EXPECT_THAT(error("image: map.pgm\nresolution: 1\norigin: [0, 0]\n"),
              HasSubstr("map.yaml: origin: expected [x, y, yaw] (3 finite numbers)"));
  EXPECT_THAT(error(base + "negate: 2\n"), HasSubstr("map.yaml: negate: expected 0 or 1"));
  EXPECT_THAT(error(base + "occupied_thresh: 1.5\n"),
              HasSubstr("map.yaml: occupied_thresh: expected a number in [0, 1]"));
  EXPECT_THAT(error(base + "free_thresh: 0.7\noccupied_thresh: 0.6\n"),
              HasSubstr("map.yaml: free_thresh: must be less than occupied_thresh"));
  EXPECT_THAT(error(base + "mode: colour\n"),
              HasSubstr("map.yaml: mode: expected trinary, scale or raw, got 'colour'"));
  EXPECT_THAT(error("image: [map.pgm]\nresolution: 1\norigin: [0, 0, 0]\n"),
              HasSubstr("map.yaml: image: expected a string"));
  EXPECT_THAT(error("image: map.pgm\nresolution: [1\n"),
              HasSubstr("map.yaml:3: YAML syntax error: end of sequence flow not found"));
  EXPECT_THAT(error("- image\n"), HasSubstr("map.yaml: expected a mapping of keys, got a list"));
}

TEST(OccupancyMapTest, ImageErrors) {
  TempDir dir;
  auto error = [&](const std::string& image_name, const std::string& image) {
    if (!image.empty()) dir.Write(image_name, image);
    const std::string path =
        dir.Write("map.yaml", "image: " + image_name + "\nresolution: 1\norigin: [0, 0, 0]\n");
    return ErrorOf([&] { ReadOccupancyMap(path); });
  };
  EXPECT_THAT(error("missing.pgm", ""),
              HasSubstr("map.yaml: image: " + dir.Path("missing.pgm") +
                        ": cannot read the file: No such file or directory"));
  // A name longer than the system allows (found by fuzz/fuzz_occupancy_map, which stopped on
  // the exception the file-system check threw; fuzz/corpus/occupancy_map/regression-*).
  EXPECT_THAT(error(std::string(300, 'x') + ".pgm", ""),
              HasSubstr(".pgm: cannot read the file: File name too long"));
  EXPECT_THAT(error("a.pgm", "P6 1 1 255\n..."),
              HasSubstr("a.pgm: not a PGM image (expected magic 'P2' or 'P5')"));
  EXPECT_THAT(error("b.pgm", "P5 4 x 255\n"),
              HasSubstr("b.pgm: malformed PGM header: expected height"));
  EXPECT_THAT(error("c.pgm", "P5 4 3 255\nabc"),
              HasSubstr("c.pgm: truncated PGM data: expected 12 pixels"));
  EXPECT_THAT(error("d.pgm", "P2 2 1 15\n3 16\n"),
              HasSubstr("d.pgm: PGM pixel 1 value 16 exceeds maxval 15"));
  EXPECT_THAT(error("e.pgm", "P2 2 1 0\n0 0\n"),
              HasSubstr("e.pgm: malformed PGM header: maxval must be in [1, 65535]"));
  EXPECT_THAT(error("g.pgm", "P2 2 1 255\n3 x\n"),
              HasSubstr("g.pgm: malformed PGM data: expected a pixel value"));
  EXPECT_THAT(error("f.png", std::string("\x89PNG\r\n\x1a\n", 8) + "garbage"),
              HasSubstr("f.png: cannot read PNG: "));
}

// Headers that promise more pixels than the file holds are errors before any memory is taken
// for them (found by fuzz/fuzz_gray_image and fuzz/fuzz_occupancy_map, which stopped on
// multi-gigabyte allocations; fuzz/corpus/gray_image/regression-*).
TEST(OccupancyMapTest, HugeImageHeadersAreTruncatedFiles) {
  TempDir dir;
  auto error = [&](const std::string& image_name, const std::string& image) {
    dir.Write(image_name, image);
    const std::string path =
        dir.Write("map.yaml", "image: " + image_name + "\nresolution: 1\norigin: [0, 0, 0]\n");
    return ErrorOf([&] { ReadOccupancyMap(path); });
  };
  EXPECT_THAT(error("a.pgm", std::string("P5 2 885888886 255\n\0\0\xff\xff", 24)),
              HasSubstr("a.pgm: truncated PGM data: expected 1771777772 pixels"));
  EXPECT_THAT(error("b.pgm", "P2 48 402515405 7 0\n"),
              HasSubstr("b.pgm: truncated PGM data: expected 19320739440 pixels, found 1"));
  // 65536 x 40000 grey pixels, 10 zero bytes of image data.
  const std::string png(
      "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x01\x00\x00"
      "\x00\x00\x9c\x40\x08\x00\x00\x00\x00\xa2\x75\x79\x85\x00\x00\x00\x0b\x49\x44\x41"
      "\x54\x78\x9c\x63\x60\x80\x01\x00\x00\x0a\x00\x01\x7f\x80\x74\x5e\x00\x00\x00\x00"
      "\x49\x45\x4e\x44\xae\x42\x60\x82",
      68);
  EXPECT_THAT(error("c.png", png),
              HasSubstr("c.png: cannot read PNG: 65536 x 40000 pixels cannot come from 68 bytes "
                        "(truncated file?)"));
}

TEST(OccupancyMapTest, SixteenBitPgm) {
  TempDir dir;
  std::string pgm = "P5 2 1 65535\n";
  pgm += std::string("\x00\x00\xff\xff", 4);
  dir.Write("map.pgm", pgm);
  const OccupancyGrid grid =
      ReadOccupancyMap(dir.Write("map.yaml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n"));
  EXPECT_EQ(grid.blocked, (std::vector<std::uint8_t>{1, 0}));
}

}  // namespace
}  // namespace acdplan::envs
