#include "envs/obj_off_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "acd/mesh_measures.h"
#include "test_util.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;

acd::TriangleMesh Obj(const std::string& text) {
  std::istringstream in(text);
  return ReadObj(in, "m.obj");
}

acd::TriangleMesh Off(const std::string& text) {
  std::istringstream in(text);
  return ReadOff(in, "m.off");
}

// Twice the vector area of the triangles: their normal times twice their total area when they
// all face one way.
Eigen::Vector3d AreaVector(const acd::TriangleMesh& mesh) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(t, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(t, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(t, 2));
    sum += (b - a).cross(c - a);
  }
  return sum;
}

TEST(ReadObjTest, KeepsEveryDigitOfAGeoreferencedVertex) {
  // Near 4.5e6 a float's step is 0.5: in floats, the first and third x would both be 4500000.
  const acd::TriangleMesh mesh =
      Obj("v 4500000.125 5300000.0625 101.3\n"
          "v 4500000.375 5300000.0625 101.3\n"
          "v 4500000.123456789 5300000.5 101.3\n"
          "f 1 2 3\n");
  ASSERT_EQ(mesh.vertices.rows(), 3);
  EXPECT_EQ(mesh.vertices(0, 0), 4500000.125);
  EXPECT_EQ(mesh.vertices(1, 0), 4500000.375);
  EXPECT_EQ(mesh.vertices(2, 0), 4500000.123456789);
  EXPECT_EQ(mesh.vertices(2, 2), 101.3);
}

TEST(ReadObjTest, ReadsCornerFormsRelativeIndicesAndSkipsWhatIsNotASurface) {
  const acd::TriangleMesh mesh =
      Obj("# a comment\r\n"
          "mtllib m.mtl\n"
          "o thing\n"
          "# from C:\\models\\\n"  // A comment ending in '\' continues nothing.
          "v 0 0 0 1 0 0\n"        // A vertex colour after the coordinates.
          "v 9 9 9\n"              // Used by the line only: dropped.
          "v 1 0 0\n"
          "v 0 1 \\\n"  // Continued on the next line.
          "  0\n"
          "v 0 0 1\n"
          "vt 0 0\nvn 0 0 1\n"
          "g side\nusemtl red\ns 1\n"
          "l 1 2\np 2\n"
          "f 1/1/1 4/1/1 3/1/1\n"
          "f 1//1 3//1 5//1  # comment\n"
          "f -5/1 -1/1 -2/1\n"
          "fo 3 4 5\n");
  ASSERT_EQ(mesh.vertices.rows(), 4);
  EXPECT_EQ(mesh.vertices.row(1), Eigen::RowVector3d(1, 0, 0));
  EXPECT_EQ(mesh.vertices.row(2), Eigen::RowVector3d(0, 1, 0));
  ASSERT_EQ(mesh.triangles.rows(), 4);
  EXPECT_EQ(mesh.triangles.row(0), Eigen::RowVector3i(0, 2, 1));
  EXPECT_EQ(mesh.triangles.row(1), Eigen::RowVector3i(0, 1, 3));
  EXPECT_EQ(mesh.triangles.row(2), Eigen::RowVector3i(0, 3, 2));
  EXPECT_EQ(mesh.triangles.row(3), Eigen::RowVector3i(1, 2, 3));
  // A positive index may name a vertex defined further down.
  EXPECT_EQ(Obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n").triangles.rows(), 1);
}

TEST(ReadObjTest, FansAConvexFaceFromItsFirstCorner) {
  // A convex hexagon, not quite planar, so the diagonals matter: those from corner 1, as other
  // OBJ readers take them (ear clipping would fan this one from corner 3).
  const acd::TriangleMesh hexagon =
      Obj("v 2 0 0\nv 1 2 0.1\nv -1 2 0\nv -2 0 0.1\nv -1 -2 0\nv 1 -2 0.1\nf 1 2 3 4 5 6\n");
  ASSERT_EQ(hexagon.triangles.rows(), 4);
  for (int t = 0; t < 4; ++t) {
    EXPECT_EQ(hexagon.triangles.row(t), Eigen::RowVector3i(0, t + 1, t + 2)) << t;
  }
}

TEST(ReadObjTest, TriangulatesANonConvexFaceKeepingItsOrientation) {
  // An L-shaped hexagon in the plane x + y = 1, and the same face listed backwards.
  const std::string vertices = "v 1 0 0\nv 1 0 2\nv 0.5 0.5 2\nv 0.5 0.5 1\nv -1 2 1\nv -1 2 0\n";
  for (const bool reversed : {false, true}) {
    const acd::TriangleMesh mesh =
        Obj(vertices + (reversed ? "f 6 5 4 3 2 1\n" : "f 1 2 3 4 5 6\n"));
    ASSERT_EQ(mesh.triangles.rows(), 4) << reversed;
    // Along the plane, s = (y - x) / sqrt(2) and z: a 4 / sqrt(2) by 1 bar and a 1 / sqrt(2)
    // by 1 arm on it.
    const double area = 5 / std::sqrt(2.0);
    // Seen from (1, 1, 0) the hexagon 1..6 turns clockwise.
    const Eigen::Vector3d normal = Eigen::Vector3d(1, 1, 0).normalized() * (reversed ? 1 : -1);
    const Eigen::Vector3d twice = AreaVector(mesh);
    EXPECT_NEAR(twice.dot(normal), 2 * area, 1e-12) << reversed;
    // No triangle overlaps another or leaves the face: their areas add up to the face's.
    EXPECT_NEAR(acd::MeshArea(mesh), area, 1e-12) << reversed;
  }
}

TEST(ReadObjTest, SkipsAUtf8ByteOrderMark) {
  // Windows editors start a file with one; it is not part of the first keyword.
  EXPECT_EQ(Obj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").vertices.rows(), 3);
  EXPECT_EQ(Off("\xEF\xBB\xBFOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").vertices.rows(), 3);
}

TEST(ReadObjTest, ErrorsNameTheLineAndTheRule) {
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(ErrorOf([&] { Obj("v 0 0\n"); }), "m.obj:1: a vertex needs 3 coordinates, got 2");
  EXPECT_EQ(ErrorOf([&] { Obj("\nv 0 0 1.2.3\n"); }), "m.obj:2: malformed number '1.2.3'");
  EXPECT_EQ(ErrorOf([&] { Obj("v 0 nan 0\n"); }), "m.obj:1: non-finite number 'nan'");
  EXPECT_EQ(ErrorOf([&] { Obj("v 0 0 1e400\n"); }), "m.obj:1: number out of range '1e400'");
  EXPECT_EQ(ErrorOf([&] { Obj(three + "f 1 2\n"); }),
            "m.obj:4: a face needs at least 3 corners, got 2");
  EXPECT_EQ(ErrorOf([&] { Obj(three + "f 1 2 0\n"); }),
            "m.obj:4: face corner '0': OBJ vertex indices start at 1 (or count back from -1)");
  EXPECT_EQ(ErrorOf([&] { Obj(three + "f 1 2 -4/1\n"); }),
            "m.obj:4: face corner '-4/1' counts back past the first vertex (3 read so far)");
  EXPECT_EQ(ErrorOf([&] { Obj(three + "f 1 2 x/1\n"); }),
            "m.obj:4: malformed face corner 'x/1' (expected v, v/vt, v//vn or v/vt/vn)");
  EXPECT_EQ(ErrorOf([&] { Obj(three + "f 1 2 4\n\n"); }),
            "m.obj:4: face refers to vertex 4, but the file has 3 vertices");
  EXPECT_EQ(ErrorOf([&] { Obj(three + "surf 0 1 0 1 1 2 3\n"); }),
            "m.obj:4: free-form surfaces ('surf') are not read: they would be lost (export "
            "polygons)");
  EXPECT_EQ(ErrorOf([&] { Obj(three + "l 1 2 3\n"); }), "m.obj: no triangles in file");
  EXPECT_EQ(ErrorOf([&] { Obj(""); }), "m.obj: no triangles in file");
}

const char* kTetraVertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const char* kTetraFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

TEST(ReadOffTest, ReadsTheHeaderVariants) {
  for (const std::string head :
       {"OFF\n4 4 6\n", "OFF 4 4 0\n", "4 4 0\n", "# c\n\nOFF\n# c\n4 4\n", "off\r\n4 4 0\r\n"}) {
    const acd::TriangleMesh mesh = Off(head + kTetraVertices + kTetraFaces);
    EXPECT_EQ(mesh.vertices.rows(), 4) << head;
    EXPECT_EQ(mesh.triangles.rows(), 4) << head;
    EXPECT_EQ(mesh.triangles.row(3), Eigen::RowVector3i(1, 2, 3)) << head;
  }
  // Colours after a vertex (COFF) or a face; a quad and a pentagon; an unused vertex.
  const acd::TriangleMesh mesh =
      Off("COFF\n6 2 0\n"
          "0 0 0 255 0 0 255\n1 0 0 255 0 0 255\n1 1 0 255 0 0 255\n0 1 0 255 0 0 255\n"
          "7 7 7 0 0 0 255\n0.5 1.5 0 0 0 0 255\n"
          "4 0 1 2 3 0.5 0.5 0.5\n5 0 1 2 5 3\n");
  EXPECT_EQ(mesh.vertices.rows(), 5);
  EXPECT_EQ(mesh.triangles.rows(), 5);
  EXPECT_NEAR(AreaVector(mesh).z(), 2 * (1 + 1.25), 1e-12);
}

TEST(ReadOffTest, ErrorsNameTheLineAndTheRule) {
  const std::string head = "OFF\n4 4 0\n";
  EXPECT_EQ(ErrorOf([&] { Off("PLY\n"); }),
            "m.off:1: expected the OFF header or the vertex count, got 'PLY'");
  EXPECT_EQ(ErrorOf([&] { Off("4OFF\n"); }), "m.off:1: '4OFF' is not 3D: only 3D OFF is read");
  EXPECT_EQ(ErrorOf([&] { Off("XOFF\n"); }), "m.off:1: unknown OFF header 'XOFF'");
  EXPECT_EQ(ErrorOf([&] { Off("OFF BINARY\n"); }),
            "m.off:1: binary OFF is not read (write it as text)");
  EXPECT_EQ(ErrorOf([&] { Off("OFF\n"); }),
            "m.off:1: the file ends before the vertex, face and edge counts");
  EXPECT_EQ(ErrorOf([&] { Off("OFF\n4 x 0\n"); }),
            "m.off:2: expected the vertex, face and edge counts, got '4 x 0'");
  EXPECT_EQ(ErrorOf([&] { Off(head + "0 0 0\n1 0 0\n"); }),
            "m.off:4: the file ends after 2 of the 4 vertices declared on line 2");
  EXPECT_EQ(ErrorOf([&] { Off(head + kTetraVertices + "3 0 2 1\n"); }),
            "m.off:7: the file ends after 1 of the 4 faces declared on line 2");
  EXPECT_EQ(ErrorOf([&] { Off(head + "0 0\n"); }), "m.off:3: a vertex needs 3 coordinates, got 2");
  EXPECT_EQ(ErrorOf([&] { Off(head + kTetraVertices + "2 0 1\n"); }),
            "m.off:7: a face starts with its number of corners, at least 3, got '2'");
  EXPECT_EQ(ErrorOf([&] { Off(head + kTetraVertices + "4 0 1 2\n"); }),
            "m.off:7: a face of 4 corners lists 3");
  EXPECT_EQ(ErrorOf([&] { Off(head + kTetraVertices + "3 0 1 4\n"); }),
            "m.off:7: face refers to vertex 4, but the vertices are 0 to 3");
  EXPECT_EQ(ErrorOf([&] { Off(head + kTetraVertices + "3 0 1 a\n"); }),
            "m.off:7: malformed vertex index 'a'");
  EXPECT_EQ(ErrorOf([&] { Off(head + kTetraVertices + kTetraFaces + "3 0 1 2\n"); }),
            "m.off:11: unexpected '3' after the 4 faces declared on line 2 (wrong count?)");
  EXPECT_EQ(ErrorOf([&] { Off("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"); }),
            "m.off: no triangles in file");
}

}  // namespace
}  // namespace acdplan::envs
