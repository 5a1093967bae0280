#include "envs/stl_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "envs/obj_off_reader.h"
#include "test_util.h"
#include "tests/data_paths.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;

acd::TriangleMesh Stl(const std::string& bytes) {
  std::istringstream in(bytes);
  return ReadStl(in, "m.stl");
}

std::string Facet(const std::string& a, const std::string& b, const std::string& c) {
  return "facet normal 0 0 0\n outer loop\n  vertex " + a + "\n  vertex " + b + "\n  vertex " + c +
         "\n endloop\nendfacet\n";
}

// A tetrahedron, outward, each corner repeated in the three facets around it.
std::string AsciiTetra(const std::string& name = "tetra") {
  return "solid " + name + "\n" + Facet("0 0 0", "0 1 0", "1 0 0") +
         Facet("0 0 0", "1 0 0", "0 0 1") + Facet("0 0 0", "0 0 1", "0 1 0") +
         Facet("1 0 0", "0 1 0", "0 0 1") + "endsolid " + name + "\n";
}

// Binary STL of `corners` (three per facet), the header starting with `header`.
std::string BinaryStl(const std::vector<std::array<float, 3>>& corners, const std::string& header) {
  std::string bytes = header;
  bytes.resize(80, '\0');
  const auto facets = static_cast<std::uint32_t>(corners.size() / 3);
  auto add = [&](const void* value, size_t size) {  // Little-endian host (x86, ARM).
    bytes.append(static_cast<const char*>(value), size);
  };
  add(&facets, 4);
  for (size_t f = 0; f < facets; ++f) {
    const float normal[3] = {0, 0, 0};
    add(normal, 12);
    for (size_t k = 0; k < 3; ++k) add(corners[3 * f + k].data(), 12);
    const std::uint16_t attribute = 0;
    add(&attribute, 2);
  }
  return bytes;
}

TEST(ReadStlTest, MergesRepeatedCornersAndKeepsEveryDigit) {
  const acd::TriangleMesh tetra = Stl(AsciiTetra());
  EXPECT_EQ(tetra.vertices.rows(), 4);
  EXPECT_EQ(tetra.triangles.rows(), 4);
  EXPECT_EQ(tetra.triangles.row(0), Eigen::RowVector3i(0, 1, 2));
  // A float's step near 4.5e6 is 0.5: assimp would have moved this corner by 0.38.
  const acd::TriangleMesh far = Stl(
      "solid far\n" + Facet("4512345.123456789 0 -0", "4512346 0 0", "4512345.123456789 1 0") +
      Facet("4512345.123456789 0 0", "4512346 1 0", "4512345.123456789 1 0") + "endsolid far\n");
  ASSERT_EQ(far.vertices.rows(), 4);  // -0 and 0 are one position.
  EXPECT_EQ(far.vertices(0, 0), 4512345.123456789);
}

TEST(ReadStlTest, ReadsWhatCadToolsWrite) {
  // Upper-case keywords, CR LF, a name with spaces, two solids one after the other, a polygon
  // facet (four corners: two triangles).
  std::string two = AsciiTetra("part one") + "SOLID second\r\n" +
                    "FACET NORMAL 0 0 1\r\nOUTER LOOP\r\nVERTEX 5 0 0\r\nVERTEX 6 0 0\r\n"
                    "VERTEX 6 1 0\r\nVERTEX 5 1 0\r\nENDLOOP\r\nENDFACET\r\nENDSOLID second\r\n";
  const acd::TriangleMesh mesh = Stl(two);
  EXPECT_EQ(mesh.vertices.rows(), 8);
  EXPECT_EQ(mesh.triangles.rows(), 6);
  // Binary, its header starting with "solid" as some CAD tools write it: told by its size.
  const std::vector<std::array<float, 3>> corners{{0, 0, 0}, {0, 1, 0},    {1, 0, 0}, {0, 0, 0},
                                                  {1, 0, 0}, {0, 0, 0.1f}, {0, 0, 0}, {0, 0, 0.1f},
                                                  {0, 1, 0}, {1, 0, 0},    {0, 1, 0}, {0, 0, 0.1f}};
  for (const char* header : {"solid part exported by a CAD tool", "binary"}) {
    const acd::TriangleMesh binary = Stl(BinaryStl(corners, header));
    EXPECT_EQ(binary.vertices.rows(), 4) << header;
    EXPECT_EQ(binary.triangles.rows(), 4) << header;
    EXPECT_EQ(binary.vertices(3, 2), static_cast<double>(0.1f)) << header;
  }
}

// A real mesh written as ASCII STL with every digit, and as binary STL (floats): each triangle
// reads back with its corners where the OBJ has them (rounded to floats in binary).
TEST(ReadStlTest, AMeshWrittenAsStlReadsBack) {
  const std::string path = test::DataDir() + "/meshes/vhacd/al.obj";
  std::ifstream file(path, std::ios::binary);
  const acd::TriangleMesh mesh = ReadObj(file, path);
  ASSERT_GT(mesh.triangles.rows(), 1000);
  std::ostringstream ascii;
  ascii.precision(17);
  ascii << "solid al\n";
  std::vector<std::array<float, 3>> corners;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    ascii << "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d p = mesh.vertices.row(mesh.triangles(t, k));
      ascii << "vertex " << p.x() << " " << p.y() << " " << p.z() << "\n";
      corners.push_back(
          {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
    }
    ascii << "endloop\nendfacet\n";
  }
  ascii << "endsolid al\n";
  const acd::TriangleMesh from_ascii = Stl(ascii.str());
  const acd::TriangleMesh from_binary = Stl(BinaryStl(corners, "al"));
  ASSERT_EQ(from_ascii.triangles.rows(), mesh.triangles.rows());
  ASSERT_EQ(from_binary.triangles.rows(), mesh.triangles.rows());
  EXPECT_EQ(from_ascii.vertices.rows(), mesh.vertices.rows());
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d p = mesh.vertices.row(mesh.triangles(t, k));
      ASSERT_EQ(from_ascii.vertices.row(from_ascii.triangles(t, k)), p) << t;
      ASSERT_EQ(from_binary.vertices.row(from_binary.triangles(t, k)),
                p.cast<float>().cast<double>())
          << t;
    }
  }
}

TEST(ReadStlTest, ErrorsNameTheLineOrTheFacet) {
  const std::string tetra = AsciiTetra();
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = tetra;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  EXPECT_EQ(ErrorOf([&] { Stl(with("  vertex 1 0 0\n endloop", "  vertex 1 0 0\n")); }),
            "m.stl:8: expected 'vertex' or 'endloop', got 'endfacet'");
  EXPECT_EQ(ErrorOf([&] { Stl(with("vertex 0 1 0", "vertex 0 1,5 0")); }),
            "m.stl:5: malformed number '1,5'");
  EXPECT_EQ(ErrorOf([&] { Stl(with("vertex 0 1 0", "vertex 0 nan 0")); }),
            "m.stl:5: non-finite number 'nan'");
  EXPECT_EQ(ErrorOf([&] { Stl(with("  vertex 0 1 0\n", "")); }),
            "m.stl:6: a facet needs at least 3 vertices, got 2");
  EXPECT_EQ(ErrorOf([&] { Stl(with("outer loop", "outer ring")); }),
            "m.stl:3: expected 'loop', got 'ring'");
  EXPECT_EQ(ErrorOf([&] { Stl(tetra.substr(0, tetra.find("endsolid"))); }),
            "m.stl:29: the file ends where 'facet' or 'endsolid' was expected");
  EXPECT_EQ(ErrorOf([&] { Stl(tetra + "extra\n"); }),
            "m.stl:31: expected 'solid' or the end of the file, got 'extra'");
  EXPECT_EQ(ErrorOf([&] { Stl("solid empty\nendsolid empty\n"); }), "m.stl: no triangles in file");
  EXPECT_EQ(ErrorOf([&] { Stl("hello\n"); }),
            "m.stl: not an STL file: ASCII STL starts with 'solid', binary STL has 84 bytes at "
            "least, this file 6");
  const std::vector<std::array<float, 3>> corners{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::string binary = BinaryStl(corners, "binary");
  EXPECT_EQ(ErrorOf([&] { Stl(binary.substr(0, 120)); }),
            "m.stl: binary STL of 1 facets needs 134 bytes, the file has 120");
  // So too when its header says "solid" (padded with spaces, no NUL in it).
  const std::string solid_header = BinaryStl(corners, std::string(80, ' ').replace(0, 5, "solid"));
  EXPECT_EQ(ErrorOf([&] { Stl(solid_header + "extra"); }),
            "m.stl: binary STL of 1 facets needs 134 bytes, the file has 139");
  std::vector<std::array<float, 3>> nan = corners;
  nan[1][2] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(ErrorOf([&] { Stl(BinaryStl(nan, "binary")); }),
            "m.stl: facet 0: a corner is not finite");
}

}  // namespace
}  // namespace acdplan::envs
