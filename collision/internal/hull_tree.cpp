#include "collision/internal/hull_tree.h"

#include <algorithm>

namespace acdplan::collision::internal {

HullTree::HullTree(const std::vector<Eigen::Matrix<double, Eigen::Dynamic, 4>>& planes,
                   const std::vector<Eigen::AlignedBox3d>& boxes, double slack) {
  for (const auto& hull : planes) {
    for (Eigen::Index r = 0; r < hull.rows(); ++r) {
      Eigen::Vector4d plane = hull.row(r).transpose();
      plane(3) += slack;
      planes_.push_back(plane);
    }
    hull_plane_begin_.push_back(static_cast<int>(planes_.size()));
  }
  std::vector<Eigen::AlignedBox3d> loose = boxes;
  for (auto& box : loose) {
    box.min().array() -= slack;
    box.max().array() += slack;
  }
  std::vector<int> ids(boxes.size());
  for (size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int>(i);
  if (!ids.empty()) Build(ids, 0, static_cast<int>(ids.size()), loose);
  order_ = ids;
}

int HullTree::Build(std::vector<int>& ids, int begin, int end,
                    const std::vector<Eigen::AlignedBox3d>& boxes) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box, centres;
  for (int i = begin; i < end; ++i) {
    box.extend(boxes[static_cast<size_t>(ids[static_cast<size_t>(i)])]);
    centres.extend(boxes[static_cast<size_t>(ids[static_cast<size_t>(i)])].center());
  }
  nodes_[static_cast<size_t>(index)].box = box;
  if (end - begin <= 4) {
    nodes_[static_cast<size_t>(index)].first = begin;
    nodes_[static_cast<size_t>(index)].count = end - begin;
    return index;
  }
  int axis = 0;
  centres.sizes().maxCoeff(&axis);
  const int mid = (begin + end) / 2;
  std::nth_element(ids.begin() + begin, ids.begin() + mid, ids.begin() + end, [&](int a, int b) {
    return boxes[static_cast<size_t>(a)].center()(axis) <
           boxes[static_cast<size_t>(b)].center()(axis);
  });
  Build(ids, begin, mid, boxes);  // left child is index + 1
  const int right = Build(ids, mid, end, boxes);
  nodes_[static_cast<size_t>(index)].first = right;
  return index;
}

bool HullTree::HullContains(int hull, const Eigen::Vector3d& p) const {
  const Eigen::Vector4d q(p.x(), p.y(), p.z(), -1.0);
  for (int k = hull_plane_begin_[static_cast<size_t>(hull)];
       k < hull_plane_begin_[static_cast<size_t>(hull) + 1]; ++k) {
    if (planes_[static_cast<size_t>(k)].dot(q) > 0) return false;
  }
  return true;
}

template <class F>
bool HullTree::Visit(const Eigen::Vector3d& p, F&& visit) const {
  if (nodes_.empty()) return false;
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int self = stack[--top];
    const Node& node = nodes_[static_cast<size_t>(self)];
    if (!node.box.contains(p)) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const int hull = order_[static_cast<size_t>(i)];
        if (HullContains(hull, p) && visit(hull)) return true;
      }
    } else {
      stack[top++] = node.first;
      stack[top++] = self + 1;
    }
  }
  return false;
}

bool HullTree::AnyContains(const Eigen::Vector3d& p) const {
  return Visit(p, [](int) { return true; });
}

void HullTree::Candidates(const Eigen::Vector3d& p, std::vector<int>* out) const {
  Visit(p, [out](int hull) {
    out->push_back(hull);
    return false;
  });
}

}  // namespace acdplan::collision::internal
