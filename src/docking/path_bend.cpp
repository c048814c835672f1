#include "docking/path_bend.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::docking {

std::optional<Path> BendPathToGoal(const Path& path, double s_from, const geometry::Pose2& goal) {
  if (path.points.size() < 2) return std::nullopt;
  const double length = path.Length();
  const double span = length - s_from;
  if (span <= 1e-6) return std::nullopt;
  // The rigid motion C with C * old goal = new goal: p -> R p + t.
  const geometry::Pose2 C = goal * path.Goal().inverse();
  const Eigen::Matrix2d R = C.rotation();
  const Eigen::Vector2d t = C.translation();
  const Eigen::Matrix2d RmI = R - Eigen::Matrix2d::Identity();

  Path bent;
  bent.points.reserve(path.points.size());
  for (const PathPoint& q : path.points) {
    PathPoint b = q;
    if (q.s > s_from) {
      const double u = std::min(1.0, (q.s - s_from) / span);
      const double w = u * u * (3.0 - 2.0 * u);
      const double dw = 6.0 * u * (1.0 - u) / span;  // dw/ds
      const Eigen::Vector2d p = q.pose.translation();
      const Eigen::Vector2d offset = RmI * p + t;  // where the full motion takes p, minus p
      const Eigen::Vector2d tangent(std::cos(q.pose.yaw), std::sin(q.pose.yaw));
      // d/ds of p + w(s) * offset(p(s)).
      const Eigen::Vector2d d = tangent + dw * offset + w * (RmI * tangent);
      b.pose =
          geometry::Pose2(p.x() + w * offset.x(), p.y() + w * offset.y(), std::atan2(d.y(), d.x()));
    }
    bent.points.push_back(b);
  }
  // The goal exactly (the smoothstep reaches 1 there; this removes rounding).
  bent.points.back().pose = goal;
  // Arc lengths and curvatures of the bent curve (central differences of the exact headings).
  for (std::size_t i = 1; i < bent.points.size(); ++i) {
    bent.points[i].s =
        bent.points[i - 1].s +
        (bent.points[i].pose.translation() - bent.points[i - 1].pose.translation()).norm();
  }
  const std::size_t n = bent.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (path.points[i].s <= s_from && i + 1 < n && path.points[i + 1].s <= s_from) continue;
    const std::size_t a = i == 0 ? 0 : i - 1;
    const std::size_t b = std::min(i + 1, n - 1);
    const double ds = bent.points[b].s - bent.points[a].s;
    if (ds > 1e-9) {
      bent.points[i].curvature =
          geometry::AngleDiff(bent.points[b].pose.yaw, bent.points[a].pose.yaw) / ds;
    }
  }
  return bent;
}

}  // namespace shelfdock::docking
