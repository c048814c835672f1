#include "docking/path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/angle.hpp"

namespace shelfdock::docking {

double Path::MaxAbsCurvature(double after_s) const {
  double k = 0.0;
  for (const PathPoint& p : points) {
    if (p.s > after_s) k = std::max(k, std::abs(p.curvature));
  }
  return k;
}

PathProjection Path::Project(const geometry::Pose2& pose, std::size_t hint) const {
  PathProjection best;
  if (points.empty()) return best;
  if (points.size() == 1) {
    const geometry::Pose2 local = points[0].pose.inverse() * pose;
    best.s = local.x;
    best.cross_track_m = local.y;
    best.heading_error_rad = local.yaw;
    return best;
  }
  const Eigen::Vector2d p = pose.translation();
  double best_d2 = std::numeric_limits<double>::infinity();
  const std::size_t last_segment = points.size() - 2;
  hint = std::min(hint, last_segment);
  for (std::size_t i = hint; i <= last_segment; ++i) {
    const Eigen::Vector2d a = points[i].pose.translation();
    const Eigen::Vector2d b = points[i + 1].pose.translation();
    const Eigen::Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
    // The last segment extends beyond the goal so overshoot reads as s > Length().
    t = i == last_segment ? std::max(t, 0.0) : std::clamp(t, 0.0, 1.0);
    const double d2 = (a + t * ab - p).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.index = i;
      best.s = points[i].s + t * std::sqrt(len2);
    }
    // Once far past the best match the rest of a smooth path cannot be closer.
    if (d2 > best_d2 + 1.0 && points[i].s > best.s + 2.0) break;
  }
  const PathPoint& a = points[best.index];
  const PathPoint& b = points[best.index + 1];
  const double seg = std::max(b.s - a.s, 1e-12);
  const double t = std::clamp((best.s - a.s) / seg, 0.0, 1.0);
  const double yaw = a.pose.yaw + t * geometry::AngleDiff(b.pose.yaw, a.pose.yaw);
  const Eigen::Vector2d tangent(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector2d foot =
      a.pose.translation() + (best.s - a.s) / seg * (b.pose.translation() - a.pose.translation());
  const Eigen::Vector2d d = p - foot;
  best.cross_track_m = tangent.x() * d.y() - tangent.y() * d.x();
  best.heading_error_rad = geometry::AngleDiff(pose.yaw, yaw);
  best.curvature = a.curvature + t * (b.curvature - a.curvature);
  return best;
}

}  // namespace shelfdock::docking
