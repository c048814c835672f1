#include "sim/path_motion.hpp"

#include <cmath>
#include <numbers>

namespace shelfdock::sim {

namespace {
std::vector<Eigen::Vector2d> Legs(const PathMotion& m) {
  std::vector<Eigen::Vector2d> pts = m.waypoints;
  if (m.closed && pts.size() > 1) pts.push_back(pts.front());
  return pts;
}
}  // namespace

double PathMotion::Length() const {
  const auto pts = Legs(*this);
  double len = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) len += (pts[i] - pts[i - 1]).norm();
  return len;
}

geometry::Pose2 PathMotion::PoseAt(double t_s) const {
  const auto pts = Legs(*this);
  if (pts.empty()) return {};
  const double len = Length();
  if (pts.size() == 1 || len <= 0.0) return {pts.front().x(), pts.front().y(), 0.0};

  // Distance travelled, folded onto the path: modulo the loop, or a back-and-forth of 2 L.
  double s = start_offset_m + speed_mps * t_s;
  bool backwards = false;
  if (closed) {
    s = std::fmod(s, len);
    if (s < 0.0) s += len;
  } else {
    s = std::fmod(s, 2.0 * len);
    if (s < 0.0) s += 2.0 * len;
    if (s > len) {
      s = 2.0 * len - s;
      backwards = true;
    }
  }
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Eigen::Vector2d e = pts[i] - pts[i - 1];
    const double seg = e.norm();
    if (s <= seg || i + 1 == pts.size()) {
      const double u = seg > 0.0 ? std::min(s / seg, 1.0) : 0.0;
      const Eigen::Vector2d p = pts[i - 1] + u * e;
      double yaw = std::atan2(e.y(), e.x());
      if (backwards) yaw += std::numbers::pi;
      return {p.x(), p.y(), yaw};
    }
    s -= seg;
  }
  return {pts.back().x(), pts.back().y(), 0.0};
}

}  // namespace shelfdock::sim
