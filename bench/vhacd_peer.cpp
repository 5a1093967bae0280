#include "bench/vhacd_peer.h"

#include <stdexcept>

#ifdef ACDPLAN_HAVE_VHACD
#define ENABLE_VHACD_IMPLEMENTATION 1
#include "VHACD.h"  // NOLINT: found through ACDPLAN_VHACD_INCLUDE_DIR (a system include).
#endif

namespace acdplan::bench {

#ifdef ACDPLAN_HAVE_VHACD

bool HaveVhacd() { return true; }

std::vector<acd::TriangleMesh> VhacdHulls(const acd::TriangleMesh& mesh) {
  std::vector<double> points(static_cast<size_t>(mesh.vertices.rows()) * 3);
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    for (int k = 0; k < 3; ++k) points[static_cast<size_t>(3 * i + k)] = mesh.vertices(i, k);
  }
  std::vector<uint32_t> triangles(static_cast<size_t>(mesh.triangles.rows()) * 3);
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      triangles[static_cast<size_t>(3 * f + k)] = static_cast<uint32_t>(mesh.triangles(f, k));
    }
  }
  VHACD::IVHACD::Parameters parameters;  // V-HACD's defaults...
  parameters.m_asyncACD = false;         // ...on this thread only.
  VHACD::IVHACD* vhacd = VHACD::CreateVHACD();
  struct Releaser {
    VHACD::IVHACD* v;
    ~Releaser() { v->Release(); }
  } releaser{vhacd};
  if (!vhacd->Compute(points.data(), static_cast<uint32_t>(mesh.vertices.rows()), triangles.data(),
                      static_cast<uint32_t>(mesh.triangles.rows()), parameters)) {
    throw std::runtime_error("V-HACD Compute() failed");
  }
  std::vector<acd::TriangleMesh> hulls;
  for (uint32_t h = 0; h < vhacd->GetNConvexHulls(); ++h) {
    VHACD::IVHACD::ConvexHull hull;
    if (!vhacd->GetConvexHull(h, hull)) throw std::runtime_error("V-HACD GetConvexHull() failed");
    acd::TriangleMesh out;
    out.vertices.resize(static_cast<Eigen::Index>(hull.m_points.size()), 3);
    for (size_t i = 0; i < hull.m_points.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      out.vertices(row, 0) = hull.m_points[i].mX;
      out.vertices(row, 1) = hull.m_points[i].mY;
      out.vertices(row, 2) = hull.m_points[i].mZ;
    }
    out.triangles.resize(static_cast<Eigen::Index>(hull.m_triangles.size()), 3);
    for (size_t t = 0; t < hull.m_triangles.size(); ++t) {
      const auto row = static_cast<Eigen::Index>(t);
      out.triangles(row, 0) = static_cast<int>(hull.m_triangles[t].mI0);
      out.triangles(row, 1) = static_cast<int>(hull.m_triangles[t].mI1);
      out.triangles(row, 2) = static_cast<int>(hull.m_triangles[t].mI2);
    }
    hulls.push_back(std::move(out));
  }
  return hulls;
}

#else

bool HaveVhacd() { return false; }

std::vector<acd::TriangleMesh> VhacdHulls(const acd::TriangleMesh&) {
  throw std::runtime_error(
      "this build has no V-HACD (configure with -DACDPLAN_VHACD_INCLUDE_DIR=<folder of VHACD.h>)");
}

#endif

}  // namespace acdplan::bench
