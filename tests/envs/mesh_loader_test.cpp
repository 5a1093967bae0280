#include "envs/mesh_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_util.h"
#include "tests/data_paths.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::TempDir;

// A unit cube with quad faces (triangulated on reading): 8 vertices, 12 triangles.
const char* kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

const char* kTetraOff =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

const char* kTetraPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

const char* kTriangleStl =
    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 2 0 0\nvertex 0 3 0\n"
    "endloop\nendfacet\nendsolid t\n";

TEST(ReadMeshTest, ReadsObjOffPlyStl) {
  TempDir dir;
  const acd::TriangleMesh cube = ReadMesh(dir.Write("cube.obj", kCubeObj));
  EXPECT_EQ(cube.triangles.rows(), 12);
  EXPECT_EQ(acd::BoundingBox(cube).min(), Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(acd::BoundingBox(cube).max(), Eigen::Vector3d(1, 1, 1));
  for (const auto& [name, text] : {std::pair{"t.off", kTetraOff}, std::pair{"t.ply", kTetraPly}}) {
    const acd::TriangleMesh tetra = ReadMesh(dir.Write(name, text));
    EXPECT_EQ(tetra.triangles.rows(), 4) << name;
    EXPECT_EQ(acd::BoundingBox(tetra).max(), Eigen::Vector3d(1, 1, 1)) << name;
  }
  const acd::TriangleMesh triangle = ReadMesh(dir.Write("t.stl", kTriangleStl));
  EXPECT_EQ(triangle.triangles.rows(), 1);
  EXPECT_EQ(acd::BoundingBox(triangle).max(), Eigen::Vector3d(2, 3, 0));
}

// One triangle in glTF 2.0 with an embedded buffer, and in COLLADA.
const char* kTriangleGltf = R"({"asset": {"version": "2.0"}, "scene": 0,
  "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "translation": [0, 0, 5]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "buffers": [{"byteLength": 36,
    "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";

const char* kTriangleDae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit meter="1" name="meter"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
      <technique_common><accessor source="#pa" count="3" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n">
    <instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";

TEST(ReadMeshTest, ReadsGltfAndCollada) {
  TempDir dir;
  const acd::TriangleMesh gltf = ReadMesh(dir.Write("t.gltf", kTriangleGltf));
  ASSERT_EQ(gltf.triangles.rows(), 1);
  EXPECT_EQ(acd::BoundingBox(gltf).max(), Eigen::Vector3d(1, 1, 5));  // Node transform applied.
  const acd::TriangleMesh dae = ReadMesh(dir.Write("t.dae", kTriangleDae));
  ASSERT_EQ(dae.triangles.rows(), 1);
  EXPECT_DOUBLE_EQ(acd::BoundingBox(dae).sizes().maxCoeff(), 1.0);
}

// Any format assimp reads is a mesh file: X3D, say, a tetrahedron moved up by its transform.
TEST(ReadMeshTest, ReadsTheOtherFormatsOfAssimp) {
  TempDir dir;
  const std::string x3d = dir.Write(
      "t.X3D",
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<X3D profile=\"Interchange\" "
      "version=\"3.3\"><Scene><Transform translation=\"0 0 4\"><Shape>"
      "<IndexedFaceSet coordIndex=\"0 2 1 -1 0 1 3 -1 0 3 2 -1 1 2 3 -1\">"
      "<Coordinate point=\"0 0 0 1 0 0 0 1 0 0 0 1\"/></IndexedFaceSet></Shape></Transform>"
      "</Scene></X3D>\n");
  ASSERT_TRUE(IsMeshFile(x3d));
  const acd::TriangleMesh mesh = ReadMesh(x3d);
  EXPECT_EQ(mesh.triangles.rows(), 4);
  EXPECT_EQ(acd::BoundingBox(mesh).min(), Eigen::Vector3d(0, 0, 4));
  EXPECT_EQ(acd::BoundingBox(mesh).max(), Eigen::Vector3d(1, 1, 5));
}

TEST(ReadMeshTest, ReadsSharedMeshes) {
  const acd::TriangleMesh cup = ReadMesh(acdplan::test::DataDir() + "/meshes/vhacd/cup.obj");
  EXPECT_GT(cup.triangles.rows(), 100);
  CheckTriangleMesh(cup, "cup.obj");
}

TEST(ReadMeshTest, Errors) {
  TempDir dir;
  EXPECT_THAT(ErrorOf([&] { ReadMesh(dir.Path("none.obj")); }),
              HasSubstr("none.obj: cannot read the file: No such file or directory"));
  EXPECT_THAT(ErrorOf([&] { ReadMesh(dir.Write("bad.ply", "ply\nformat nonsense 1.0\n")); }),
              HasSubstr("bad.ply:2: unknown format 'nonsense'"));
  EXPECT_THAT(ErrorOf([&] { ReadMesh(dir.Write("bad.xyz123", "hello")); }),
              HasSubstr("bad.xyz123: cannot read mesh: "));
  EXPECT_THAT(ErrorOf([&] { ReadMesh(dir.Write("points.obj", "v 0 0 0\nv 1 0 0\n")); }),
              HasSubstr("points.obj: no triangles in file"));
  EXPECT_THAT(ErrorOf([&] { ReadMesh(dir.Write("bad.OFF", "OFF\n3 1 0\n0 0 0\n")); }),
              HasSubstr("bad.OFF:3: the file ends after 1 of the 3 vertices declared on line 2"));
  // 1e75 is a finite double, but assimp reads floats: the message says why it is not finite.
  std::string far_dae = kTriangleDae;
  far_dae.replace(far_dae.find("0 0 0 1 0 0"), 11, "0 0 0 1e75 0 0");
  EXPECT_THAT(ErrorOf([&] { ReadMesh(dir.Write("far.dae", far_dae)); }),
              HasSubstr("far.dae: mesh 0, vertex 1: a coordinate is not finite as read (NaN or "
                        "infinite, or beyond 3.4e38"));
  // In OBJ, PLY and ASCII STL it is read as it is.
  const acd::TriangleMesh far =
      ReadMesh(dir.Write("far.obj", "v 0 0 0\nv 1e75 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_EQ(far.vertices(1, 0), 1e75);
  std::string far_ply = kTetraPly;
  far_ply.replace(far_ply.find("\n1 0 0\n"), 7, "\n1e75 0 0\n");
  EXPECT_EQ(ReadMesh(dir.Write("far.ply", far_ply)).vertices(1, 0), 1e75);
  std::string far_stl = kTriangleStl;
  far_stl.replace(far_stl.find("vertex 2 0 0"), 12, "vertex 1e75 0 0");
  EXPECT_EQ(ReadMesh(dir.Write("far.stl", far_stl)).vertices(1, 0), 1e75);
}

TEST(IsMeshFileTest, ByExtensionInAnyCase) {
  for (const char* path : {"a.obj", "b/c.OFF", "d.Ply", "e.stl", "f.dae", "g.gltf", "h.GLB",
                           "i.fbx", "j.3DS", "k.3mf", "l.x3d", "m.blend"}) {
    EXPECT_TRUE(IsMeshFile(path)) << path;
  }
  // Not the formats of the other loaders, nor a shapefile's sidecar files.
  for (const char* path :
       {"a.poly", "world.yaml", "w.yml", "map.map", "p.wkt", "p.geojson", "p.json", "p.shp",
        "p.prj", "p.dbf", "map.pgm", "obj", "a.obj.txt", "mesh"}) {
    EXPECT_FALSE(IsMeshFile(path)) << path;
  }
}

TEST(CheckTriangleMeshTest, Errors) {
  acd::TriangleMesh mesh;
  EXPECT_EQ(ErrorOf([&] { CheckTriangleMesh(mesh, "m"); }), "m: mesh has no triangles");
  mesh.vertices.resize(3, 3);
  mesh.vertices.setZero();
  mesh.triangles.resize(1, 3);
  mesh.triangles << 0, 1, 3;
  EXPECT_EQ(ErrorOf([&] { CheckTriangleMesh(mesh, "m"); }),
            "m: triangle 0: index 3 out of range [0, 3)");
}

}  // namespace
}  // namespace acdplan::envs
