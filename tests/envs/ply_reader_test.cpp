#include "envs/ply_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "envs/obj_off_reader.h"
#include "test_util.h"
#include "tests/data_paths.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;

acd::TriangleMesh Ply(const std::string& bytes) {
  std::istringstream in(bytes);
  return ReadPly(in, "m.ply");
}

// Values appended to a binary PLY body in the chosen byte order.
class Bytes {
 public:
  explicit Bytes(bool big_endian) : big_endian_(big_endian) {}

  template <typename T>
  Bytes& Add(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    const std::uint16_t one = 1;
    const bool host_big = *reinterpret_cast<const unsigned char*>(&one) == 0;
    if (host_big != big_endian_) std::reverse(raw, raw + sizeof(T));
    text.append(raw, sizeof(T));
    return *this;
  }

  std::string text;

 private:
  bool big_endian_;
};

const char* const kAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
    "property double z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
const char* const kTetraData = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

TEST(ReadPlyTest, KeepsEveryDigitOfAGeoreferencedVertex) {
  // A float's step near 4.5e6 is 0.5: assimp would have moved this vertex by 0.38 and 0.49.
  const acd::TriangleMesh mesh = Ply(std::string(kAsciiHeader) +
                                     "4512345.123456789 5412345.987654321 12.000000001\n"
                                     "4512346 5412345 12\n4512345 5412346 12\n4512345 5412345 13\n"
                                     "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ASSERT_EQ(mesh.vertices.rows(), 4);
  EXPECT_EQ(mesh.vertices(0, 0), 4512345.123456789);
  EXPECT_EQ(mesh.vertices(0, 1), 5412345.987654321);
  EXPECT_EQ(mesh.vertices(0, 2), 12.000000001);
  EXPECT_EQ(mesh.triangles.rows(), 4);
}

TEST(ReadPlyTest, SkipsWhatCarriesNoSurfaceAndTriangulatesPolygons) {
  // Comments, normals and colours, a texture-coordinate list before the corners, an edge
  // element, CR LF line ends, faces declared before the vertices they use, a quad and a
  // vertex no face uses (dropped).
  const std::string text =
      "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info test\r\n"
      "element face 2\r\nproperty list uchar float texcoord\r\n"
      "property list uchar uint vertex_index\r\n"
      "element vertex 5\r\nproperty float nx\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nproperty uchar red\r\n"
      "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
      "2 0.5 0.5 4 0 1 2 3\r\n0 3 0 3 4\r\n"
      "1 0 0 0 255\r\n1 2 0 0 255\r\n1 2 2 0 255\r\n1 0 2 0 255\r\n1 0 0 1 255\r\n"
      "0 1\r\n";
  const acd::TriangleMesh mesh = Ply(text);
  ASSERT_EQ(mesh.vertices.rows(), 5);
  EXPECT_EQ(mesh.vertices.row(2), Eigen::RowVector3d(2, 2, 0));
  ASSERT_EQ(mesh.triangles.rows(), 3);  // The quad in two, the triangle 0 3 4.
  EXPECT_EQ(mesh.triangles.row(2), Eigen::RowVector3i(0, 3, 4));
}

TEST(ReadPlyTest, ReadsBinaryInBothByteOrders) {
  for (const bool big : {false, true}) {
    // A triangle with doubles and a float beside them, one uchar colour, uint32 corners.
    Bytes body(big);
    const double x = 4512345.123456789;
    body.Add(x).Add(1.0).Add(2.5f).Add(std::uint8_t{7});
    body.Add(x + 1).Add(1.0).Add(2.5f).Add(std::uint8_t{7});
    body.Add(x).Add(2.0).Add(-0.1f).Add(std::uint8_t{7});
    body.Add(std::uint8_t{3}).Add(std::uint32_t{0}).Add(std::uint32_t{1}).Add(std::uint32_t{2});
    const std::string header =
        std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
        " 1.0\nelement vertex 3\nproperty float64 x\nproperty double y\nproperty float z\n"
        "property uchar red\nelement face 1\nproperty list uint8 uint32 vertex_indices\n"
        "end_header\n";
    const acd::TriangleMesh mesh = Ply(header + body.text);
    ASSERT_EQ(mesh.vertices.rows(), 3) << big;
    EXPECT_EQ(mesh.vertices(0, 0), x) << big;
    EXPECT_EQ(mesh.vertices(1, 0), x + 1) << big;
    EXPECT_EQ(mesh.vertices(2, 2), static_cast<double>(-0.1f)) << big;
    EXPECT_EQ(mesh.triangles.row(0), Eigen::RowVector3i(0, 1, 2)) << big;
    // Truncated inside the face: named by element and index.
    EXPECT_EQ(ErrorOf([&] { Ply(header + body.text.substr(0, body.text.size() - 2)); }),
              "m.ply: face 0: the file ends inside it (1 declared on line 8)");
    // A face more than declared.
    EXPECT_EQ(ErrorOf([&] { Ply(header + body.text + body.text.substr(body.text.size() - 13)); }),
              "m.ply: 13 bytes after the declared elements (wrong count?)");
    EXPECT_NO_THROW(Ply(header + body.text + "\n"));  // A line end some writers append.
  }
  Bytes nan(false);
  nan.Add(std::numeric_limits<float>::quiet_NaN()).Add(0.0f).Add(0.0f);
  EXPECT_EQ(ErrorOf([&] {
              Ply("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                  "property float y\nproperty float z\nelement face 1\n"
                  "property list uchar int vertex_indices\nend_header\n" +
                  nan.text);
            }),
            "m.ply: vertex 0: coordinate x is not finite");
}

// A real mesh written as binary PLY with doubles, in either byte order, reads back exactly as
// the OBJ it came from (its polygons were triangulated on the way: the faces are triangles).
TEST(ReadPlyTest, AMeshWrittenAsBinaryPlyReadsBackExactly) {
  const std::string path = test::DataDir() + "/meshes/vhacd/al.obj";
  std::ifstream file(path, std::ios::binary);
  const acd::TriangleMesh mesh = ReadObj(file, path);
  ASSERT_GT(mesh.triangles.rows(), 1000);
  for (const bool big : {false, true}) {
    Bytes body(big);
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      body.Add(mesh.vertices(v, 0)).Add(mesh.vertices(v, 1)).Add(mesh.vertices(v, 2));
    }
    for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
      body.Add(std::uint8_t{3});
      for (int k = 0; k < 3; ++k) body.Add(static_cast<std::int32_t>(mesh.triangles(t, k)));
    }
    const std::string header =
        std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
        " 1.0\nelement vertex " + std::to_string(mesh.vertices.rows()) +
        "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
        std::to_string(mesh.triangles.rows()) +
        "\nproperty list uchar int vertex_indices\nend_header\n";
    const acd::TriangleMesh read = Ply(header + body.text);
    EXPECT_EQ(read.vertices, mesh.vertices) << big;
    EXPECT_EQ(read.triangles, mesh.triangles) << big;
  }
}

TEST(ReadPlyTest, ErrorsNameTheLineAndTheRule) {
  const std::string header = kAsciiHeader;
  auto with = [&](const std::string& line, const std::string& replacement) {
    std::string text = header;
    text.replace(text.find(line), line.size(), replacement);
    return text + kTetraData;
  };
  EXPECT_EQ(ErrorOf([&] { Ply("OFF\n"); }),
            "m.ply:1: not a PLY file (its first line must be 'ply')");
  EXPECT_EQ(ErrorOf([&] { Ply(with("format ascii 1.0", "format ascii 2.0")); }),
            "m.ply:2: expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
  EXPECT_EQ(ErrorOf([&] { Ply(with("format ascii", "format text")); }),
            "m.ply:2: unknown format 'text'");
  EXPECT_EQ(ErrorOf([&] { Ply(with("property double y", "property real y")); }),
            "m.ply:5: unknown property type 'real'");
  EXPECT_EQ(ErrorOf([&] { Ply(with("property double z", "property double y")); }),
            "m.ply:6: property 'y' of element 'vertex' declared twice");
  EXPECT_EQ(ErrorOf([&] { Ply(with("property double z\n", "")); }),
            "m.ply:3: element 'vertex' has no property 'z'");
  EXPECT_EQ(ErrorOf([&] { Ply(with("uchar int vertex", "uchar float vertex")); }),
            "m.ply:8: vertex indices must have an integer type, not 'float'");
  EXPECT_EQ(ErrorOf([&] { Ply(with("vertex_indices", "corners")); }),
            "m.ply:7: element 'face' has no list property 'vertex_indices'");
  EXPECT_EQ(ErrorOf([&] { Ply(with("element vertex 4", "element vertex four")); }),
            "m.ply:3: expected 'element <name> <count>', the count a whole number >= 0");
  EXPECT_EQ(ErrorOf([&] { Ply(with("end_header", "end_head")); }),
            "m.ply:9: unknown header keyword 'end_head'");
  EXPECT_EQ(ErrorOf([&] { Ply("ply\nformat ascii 1.0\nelement vertex 3\n"); }),
            "m.ply:3: the header does not end (no 'end_header' line)");
  EXPECT_EQ(ErrorOf([&] { Ply(with("format ascii 1.0\n", "")); }),
            "m.ply:8: the header has no 'format' line");
  EXPECT_EQ(ErrorOf([&] { Ply(with("element face 4", "element face 0")); }),
            "m.ply: no triangles in file");
  EXPECT_EQ(ErrorOf([&] { Ply(with("element face 4", "element tristrips 1")); }),
            "m.ply:7: triangle strips ('tristrips') are not read: they would be lost (export "
            "faces)");
  // The data.
  EXPECT_EQ(ErrorOf([&] { Ply(header + "0 0 0\n1 0 nan\n"); }),
            "m.ply:11: non-finite number 'nan'");
  EXPECT_EQ(ErrorOf([&] { Ply(header + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 9\n"); }),
            "m.ply:15: face refers to vertex 9, but the vertices are 0 to 3");
  EXPECT_EQ(ErrorOf([&] { Ply(header + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n2 0 2\n"); }),
            "m.ply:14: a face needs at least 3 corners, got 2");
  EXPECT_EQ(ErrorOf([&] { Ply(header + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 x\n"); }),
            "m.ply:15: malformed integer 'x'");
  EXPECT_EQ(ErrorOf([&] { Ply(header + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1\n"); }),
            "m.ply:15: the file ends inside face 1 of the 4 declared on line 7");
  EXPECT_EQ(ErrorOf([&] { Ply(header + kTetraData + "3 0 1 2\n"); }),
            "m.ply:18: unexpected '3' after the declared elements (wrong count?)");
}

}  // namespace
}  // namespace acdplan::envs
