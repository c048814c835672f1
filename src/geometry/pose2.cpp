#include "geometry/pose2.hpp"

#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::geometry {

Pose2::Pose2(double x_m, double y_m, double yaw_rad) : x(x_m), y(y_m), yaw(WrapAngle(yaw_rad)) {}

Eigen::Matrix2d Pose2::rotation() const {
  const double c = std::cos(yaw);
  const double s = std::sin(yaw);
  Eigen::Matrix2d r;
  r << c, -s, s, c;
  return r;
}

Pose2 Pose2::operator*(const Pose2& rhs) const {
  const Eigen::Vector2d t = (*this) * rhs.translation();
  return {t.x(), t.y(), yaw + rhs.yaw};
}

Eigen::Vector2d Pose2::operator*(const Eigen::Vector2d& p) const {
  return rotation() * p + translation();
}

Pose2 Pose2::inverse() const {
  const Eigen::Vector2d t = -(rotation().transpose() * translation());
  return {t.x(), t.y(), -yaw};
}

double Distance(const Pose2& a, const Pose2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace shelfdock::geometry
