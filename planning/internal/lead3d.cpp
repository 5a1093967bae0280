#include "planning/internal/lead3d.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace acdplan::planning::internal {

double RobotWidth3d(const Eigen::Matrix<double, Eigen::Dynamic, 3>& vertices) {
  if (vertices.rows() < 2) return 0.0;
  const Eigen::RowVector3d mean = vertices.colwise().mean();
  const Eigen::Matrix<double, Eigen::Dynamic, 3> centred = vertices.rowwise() - mean;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(centred.transpose() * centred);
  double width = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const Eigen::VectorXd along = centred * solver.eigenvectors().col(k).normalized();
    width = std::min(width, along.maxCoeff() - along.minCoeff());
  }
  return width;
}

int LocateComponent3d(const envs::FreeSpaceDecomposition3d& decomposition,
                      const Eigen::Vector3d& p) {
  if (decomposition.components.empty()) return -1;
  const int located = decomposition.Locate(p);
  if (located >= 0) return located;
  return NearestCentroid(decomposition.components, p);
}

Lead FindLead3d(const envs::FreeSpaceDecomposition3d& decomposition, int from, int to,
                double robot_width, double narrow_penalty) {
  const int n = static_cast<int>(decomposition.components.size());
  // A component thinner than the robot (a sliver the ACD cut beside a passage) cannot hold it
  // on the way through either: the ways into it pay the penalty too.
  std::vector<bool> thin(decomposition.components.size(), false);
  if (robot_width > 0) {
    for (size_t c = 0; c < thin.size(); ++c) {
      thin[c] = RobotWidth3d(decomposition.components[c].hull.vertices) < robot_width;
    }
  }
  std::vector<LeadEdge> edges;
  for (const envs::FreeOpening3d& opening : decomposition.openings) {
    LeadEdge edge{opening.component_a, opening.component_b, 0.0};
    if (edge.a >= 0 && edge.b >= 0 && edge.a < n && edge.b < n) {
      edge.cost = (decomposition.components[edge.a].centroid - opening.centroid).norm() +
                  (opening.centroid - decomposition.components[edge.b].centroid).norm();
      if (opening.width < robot_width || thin[edge.a] || thin[edge.b]) edge.cost *= narrow_penalty;
    }
    edges.push_back(edge);
  }
  return ShortestLead(n, edges, from, to);
}

HullSampler3d::HullSampler3d(const envs::FreeComponent3d& component)
    : planes_(component.planes), centroid_(component.centroid), volume_(component.volume) {
  for (Eigen::Index i = 0; i < component.hull.vertices.rows(); ++i) {
    box_.extend(component.hull.vertices.row(i).transpose());
  }
}

bool HullSampler3d::Contains(const Eigen::Vector3d& p) const {
  if (planes_.rows() == 0) return false;
  return (planes_ * Eigen::Vector4d(p.x(), p.y(), p.z(), -1.0)).maxCoeff() <= 0;
}

Eigen::Vector3d HullSampler3d::Sample(RandomEngine& rng) const {
  return Sample([&rng] { return UniformReal(rng, 0.0, 1.0); });
}

Eigen::Vector3d HullSampler3d::Sample(const std::function<double()>& unit) const {
  if (box_.isEmpty()) return centroid_;
  for (int attempt = 0; attempt < kMaxRejections; ++attempt) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p[k] = box_.min()[k] + unit() * (box_.max()[k] - box_.min()[k]);
    if (Contains(p)) return p;
  }
  return centroid_;
}

LeadDistribution3d::LeadDistribution3d(const envs::FreeSpaceDecomposition3d& decomposition,
                                       const LeadQuery3d& query,
                                       const AcdSamplerOptions& sampler_options,
                                       const AcdLeadOptions& lead_options,
                                       const LongAxis3d& long_axis)
    : options_(sampler_options),
      lead_options_(lead_options),
      targets_(decomposition, sampler_options, long_axis) {
  if (decomposition.components.empty()) {
    throw std::invalid_argument("acd_lead: the 3D decomposition has no components");
  }
  const int from = LocateComponent3d(decomposition, query.start);
  const int to = LocateComponent3d(decomposition, query.goal);
  lead_ = FindLead3d(decomposition, from, to, query.robot_width, lead_options.narrow_penalty);

  std::vector<bool> usable_component, usable_opening;
  std::vector<double> size;
  for (const envs::FreeComponent3d& component : decomposition.components) {
    components_.emplace_back(component);
    usable_component.push_back(component.volume > 0 && component.planes.rows() > 0);
    size.push_back(std::cbrt(std::max(component.volume, 0.0)));
  }
  // Narrower openings draw more (AcdTargets3d's law: mean width / width, capped at
  // max_narrowness): a lead through rooms cut by wide planes puts its draws at the hatches.
  double total_width = 0;
  int widths = 0;
  for (const envs::FreeOpening3d& opening : decomposition.openings) {
    if (opening.width > 0) total_width += opening.width, ++widths;
  }
  const double mean_width = widths > 0 ? total_width / widths : 0.0;
  std::vector<LeadEdge> edges;
  std::vector<Eigen::Vector3d> centroids;
  for (const envs::FreeOpening3d& opening : decomposition.openings) {
    OpeningShape shape;
    shape.centroid = opening.centroid;
    shape.normal = opening.normal.normalized();
    shape.sigma_normal = sampler_options.opening_spread * std::max(opening.width, long_axis.length);
    shape.sigma_plane = sampler_options.opening_spread *
                        std::max(opening.width - long_axis.thickness, 0.1 * opening.width);
    double sum = 0;
    const size_t n = opening.polygon.size();
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d& a = opening.polygon[i];
      const Eigen::Vector3d& b = opening.polygon[(i + 1) % n];
      sum += 0.5 * (a - shape.centroid).cross(b - shape.centroid).norm();
      shape.fan.push_back(a);
      shape.fan.push_back(b);
      shape.cumulative.push_back(sum);
    }
    usable_opening.push_back(opening.width > 0 && sum > 0);
    openings_.push_back(std::move(shape));
    LeadEdge edge{opening.component_a, opening.component_b};
    if (opening.width > 0) {
      edge.weight = std::min(mean_width / opening.width, sampler_options.max_narrowness);
    }
    edges.push_back(edge);
    centroids.push_back(opening.centroid);
  }
  levels_ =
      LeadLevels(lead_, edges, usable_component, usable_opening,
                 LengthsAlongLead(lead_, size, query.start, query.goal, centroids), lead_options);
}

AcdDraw3d LeadDistribution3d::Draw(RandomEngine& rng, int level, double pick_u, int* part) const {
  level = std::min(std::max(level, 0), 2);
  const double uniform_share =
      level < 2 ? lead_options_.lead_uniform_share : options_.uniform_share;
  const LeadPart* picked = levels_.Pick(level, pick_u);
  if (!picked || UniformReal(rng, 0.0, 1.0) < uniform_share) return AcdDraw3d{};
  AcdDraw3d draw;
  draw.uniform = false;
  if (!picked->opening) {
    draw.position = components_[picked->index].Sample(rng);
    if (part) *part = picked->index;
    return draw;
  }
  // Uniform on the opening polygon shrunk to 80% (a fan triangle by area, then a uniform
  // point of it), then off its plane along the normal.
  const OpeningShape& shape = openings_[picked->index];
  if (UniformIndex(rng, 2)) {
    // Half the draws as AcdTargets3d: Gaussian about the centroid with the robot's play.
    const Eigen::Vector3d n = shape.normal;
    const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
    const double g1 = StandardNormal(rng), g2 = StandardNormal(rng), g3 = StandardNormal(rng);
    draw.position =
        shape.centroid + shape.sigma_plane * (g1 * a + g2 * b) + shape.sigma_normal * g3 * n;
  } else {
    const double u = UniformReal(rng, 0.0, shape.cumulative.back());
    const size_t t =
        std::min<size_t>(std::upper_bound(shape.cumulative.begin(), shape.cumulative.end(), u) -
                             shape.cumulative.begin(),
                         shape.cumulative.size() - 1);
    double r1 = UniformReal(rng, 0.0, 1.0), r2 = UniformReal(rng, 0.0, 1.0);
    if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
    const Eigen::Vector3d in_plane =
        r1 * (shape.fan[2 * t] - shape.centroid) + r2 * (shape.fan[2 * t + 1] - shape.centroid);
    draw.position =
        shape.centroid + 0.8 * in_plane + shape.sigma_normal * StandardNormal(rng) * shape.normal;
  }
  if (options_.orientation == AcdOrientation::kAligned &&
      targets_.long_axis().axis.squaredNorm() > 0) {
    draw.has_rotation = true;
    draw.rotation = targets_.AlignedRotation(rng, shape.normal);
  }
  if (part) *part = -1 - picked->index;
  return draw;
}

}  // namespace acdplan::planning::internal
