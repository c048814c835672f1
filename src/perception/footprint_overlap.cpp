#include "perception/footprint_overlap.hpp"

#include <array>
#include <cmath>

#include <Eigen/Core>

namespace shelfdock::perception {
namespace {

// Half the extent of `r` projected on the unit axis `n`.
double HalfProjection(const OrientedRect& r, const Eigen::Vector2d& n) {
  const Eigen::Vector2d ex(std::cos(r.pose.yaw), std::sin(r.pose.yaw));
  const Eigen::Vector2d ey(-ex.y(), ex.x());
  return r.half_x_m * std::abs(n.dot(ex)) + r.half_y_m * std::abs(n.dot(ey));
}

}  // namespace

bool RectsOverlap(const OrientedRect& a, const OrientedRect& b) {
  if (a.half_x_m <= 0.0 || a.half_y_m <= 0.0 || b.half_x_m <= 0.0 || b.half_y_m <= 0.0) {
    return false;
  }
  const Eigen::Vector2d d = b.pose.translation() - a.pose.translation();
  const std::array<double, 2> yaws{a.pose.yaw, b.pose.yaw};
  for (const double yaw : yaws) {
    const Eigen::Vector2d ex(std::cos(yaw), std::sin(yaw));
    const Eigen::Vector2d ey(-ex.y(), ex.x());
    for (const Eigen::Vector2d& n : {ex, ey}) {
      if (std::abs(d.dot(n)) >= HalfProjection(a, n) + HalfProjection(b, n)) return false;
    }
  }
  return true;
}

}  // namespace shelfdock::perception
