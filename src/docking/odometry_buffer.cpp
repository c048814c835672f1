#include "docking/odometry_buffer.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::docking {

void OdometryBuffer::Add(double t_s, const geometry::Pose2& T_odom_base) {
  if (!samples_.empty() && t_s <= samples_.back().t_s) {
    samples_.back() = {t_s, T_odom_base};
    return;
  }
  samples_.push_back({t_s, T_odom_base});
  while (samples_.size() > 2 && samples_.front().t_s < t_s - keep_s_) samples_.pop_front();
}

geometry::Pose2 OdometryBuffer::At(double t_s) const {
  if (samples_.empty()) return {};
  if (t_s <= samples_.front().t_s) return samples_.front().T_odom_base;
  if (t_s >= samples_.back().t_s) return samples_.back().T_odom_base;
  const auto upper = std::lower_bound(samples_.begin(), samples_.end(), t_s,
                                      [](const Sample& s, double t) { return s.t_s < t; });
  const Sample& b = *upper;
  const Sample& a = *(upper - 1);
  const double u = (t_s - a.t_s) / std::max(b.t_s - a.t_s, 1e-12);
  const geometry::Pose2& pa = a.T_odom_base;
  const geometry::Pose2& pb = b.T_odom_base;
  return {pa.x + u * (pb.x - pa.x), pa.y + u * (pb.y - pa.y),
          pa.yaw + u * geometry::AngleDiff(pb.yaw, pa.yaw)};
}

std::vector<perception::ScanPoint> CompensatedPoints(const geometry::LaserScan& scan,
                                                     const OdometryBuffer& odometry,
                                                     const geometry::Pose2& T_base_lidar,
                                                     double t_ref_s) {
  std::vector<perception::ScanPoint> points;
  points.reserve(scan.ranges.size());
  const geometry::Pose2 T_lidarref_odom = (odometry.At(t_ref_s) * T_base_lidar).inverse();
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!scan.HasReturn(i)) continue;
    const double r = scan.ranges[i];
    const double a = scan.BeamAngle(i);
    const Eigen::Vector2d p_lidar_i(r * std::cos(a), r * std::sin(a));
    const double t_i = scan.stamp + static_cast<double>(i) * scan.time_increment;
    const geometry::Pose2 T_ref_i = T_lidarref_odom * odometry.At(t_i) * T_base_lidar;
    perception::ScanPoint sp;
    sp.p = T_ref_i * p_lidar_i;
    sp.range = sp.p.norm();
    sp.angle = std::atan2(sp.p.y(), sp.p.x());
    sp.beam = static_cast<int>(i);
    points.push_back(sp);
  }
  return points;
}

}  // namespace shelfdock::docking
