#include "sim/path_motion.hpp"

#include <cmath>
#include <numbers>

namespace shelfdock::sim {

namespace {
/// Waypoint k of the traversed polyline; a closed path repeats its first point at the end.
const Eigen::Vector2d& Point(const PathMotion& m, std::size_t k) {
  return m.waypoints[k % m.waypoints.size()];
}
std::size_t NumPoints(const PathMotion& m) {
  const std::size_t n = m.waypoints.size();
  return m.closed && n > 1 ? n + 1 : n;
}
}  // namespace

double PathMotion::Length() const {
  double len = 0.0;
  for (std::size_t i = 1; i < NumPoints(*this); ++i) {
    len += (Point(*this, i) - Point(*this, i - 1)).norm();
  }
  return len;
}

geometry::Pose2 PathMotion::PoseAt(double t_s) const {
  const std::size_t n = NumPoints(*this);
  if (n == 0) return {};
  const double len = Length();
  if (n == 1 || len <= 0.0) return {waypoints.front().x(), waypoints.front().y(), 0.0};

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
  for (std::size_t i = 1; i < n; ++i) {
    const Eigen::Vector2d e = Point(*this, i) - Point(*this, i - 1);
    const double seg = e.norm();
    if (s <= seg || i + 1 == n) {
      const double u = seg > 0.0 ? std::min(s / seg, 1.0) : 0.0;
      const Eigen::Vector2d p = Point(*this, i - 1) + u * e;
      double yaw = std::atan2(e.y(), e.x());
      if (backwards) yaw += std::numbers::pi;
      return {p.x(), p.y(), yaw};
    }
    s -= seg;
  }
  return {Point(*this, n - 1).x(), Point(*this, n - 1).y(), 0.0};
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const PathMotion& m) {
  geometry::ConfigChecker k;
  k.Check(m.speed_mps >= 0.0 && m.speed_mps < 10.0, "speed", "in [0, 10) m/s");
  return k.Result();
}

}  // namespace shelfdock::sim
