#pragma once
// Test helpers: the paper's shelf models and simulated scenes (sim::World + sim::Lidar), plus an
// analytic ray caster for stage tests that need exact points on one leg.

#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "../common/paper_models.hpp"
#include "geometry/angle.hpp"
#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/preprocess.hpp"
#include "sim/lidar.hpp"
#include "sim/world.hpp"

namespace shelfdock::perception::testing {

using shelfdock::testing::MakeModel;
using shelfdock::testing::PaperModels;

/// The WLR-716's angle increment: 1/3 degree.
inline constexpr double kWlrAlpha = 0.005817764173314432;

/// An exact return at `range` on beam `beam` of a fan starting at angle 0 in kWlrAlpha steps.
inline ScanPoint BeamPoint(int beam, double range) {
  const double a = beam * kWlrAlpha;
  return {Eigen::Vector2d(range * std::cos(a), range * std::sin(a)), range, a, beam};
}

/// A 12 m x 10 m room around the origin (walls far behind every test shelf).
inline void AddRoom(sim::World& world) {
  world.AddWall({{-5.0, -5.0}, {7.0, -5.0}, {7.0, 5.0}, {-5.0, 5.0}}, true);
}

/// A scan of `world` from a LiDAR at T_world_lidar with the WLR-716 defaults (10 mm noise,
/// mixed points, dropouts) unless `config` is given.
inline geometry::LaserScan SimScan(const sim::World& world, const geometry::Pose2& T_world_lidar,
                                   std::uint64_t seed, sim::LidarConfig config = {}) {
  sim::Lidar lidar(config, seed);
  return lidar.Scan(world, T_world_lidar);
}

/// Smallest heading error modulo the model's symmetry (ShelfModel::HeadingPeriod: pi, or pi/2
/// for squares).
inline double SymmetricYawError(double yaw, double truth, const geometry::ShelfModel& model) {
  return geometry::AngleDiffModulo(yaw, truth, model.HeadingPeriod());
}

/// Exact points of a ray fan (sensor at the origin) on a circle or an oriented box: the first
/// hit of each beam, angle_increment apart, in beam order. For leg-fit tests.
inline std::vector<ScanPoint> CastCircle(const Eigen::Vector2d& centre, double radius,
                                         double angle_increment) {
  std::vector<ScanPoint> out;
  const double bearing = std::atan2(centre.y(), centre.x());
  const double half = std::asin(std::min(1.0, radius / centre.norm()));
  int beam = 0;
  for (double a = bearing - half; a <= bearing + half; a += angle_increment, ++beam) {
    const Eigen::Vector2d u(std::cos(a), std::sin(a));
    const double b = u.dot(centre);
    const double disc = b * b - (centre.squaredNorm() - radius * radius);
    if (disc < 0.0) continue;
    const double t = b - std::sqrt(disc);
    out.push_back({t * u, t, a, beam});
  }
  return out;
}

/// The range at which the ray from the origin at `angle` first hits the oriented box (slab test
/// in the box frame); nullopt when it misses.
inline std::optional<double> RayBoxRange(const geometry::Pose2& T_lidar_box, double length,
                                         double width, double angle) {
  const geometry::Pose2 T_box_lidar = T_lidar_box.inverse();
  const Eigen::Vector2d o = T_box_lidar * Eigen::Vector2d::Zero();
  const Eigen::Vector2d d =
      T_box_lidar.rotation() * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  double t0 = -1e9, t1 = 1e9;
  const double h[2] = {0.5 * length, 0.5 * width};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(d[k]) < 1e-12) {
      if (std::abs(o[k]) > h[k]) return std::nullopt;
      continue;
    }
    double ta = (-h[k] - o[k]) / d[k], tb = (h[k] - o[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1 || t0 <= 0.0) return std::nullopt;
  return t0;
}

inline std::vector<ScanPoint> CastBox(const geometry::Pose2& T_lidar_box, double length,
                                      double width, double angle_increment) {
  std::vector<ScanPoint> out;
  const double bearing = std::atan2(T_lidar_box.y, T_lidar_box.x);
  const double half = std::atan2(std::hypot(length, width), T_lidar_box.translation().norm());
  int beam = 0;
  for (double a = bearing - half; a <= bearing + half; a += angle_increment, ++beam) {
    const std::optional<double> t = RayBoxRange(T_lidar_box, length, width, a);
    if (!t) continue;
    out.push_back({Eigen::Vector2d(*t * std::cos(a), *t * std::sin(a)), *t, a, beam});
  }
  return out;
}

/// Exact points of a ray fan on one leg section centred and turned as T_lidar_leg (a round leg
/// ignores the turn): CastCircle or CastBox.
inline std::vector<ScanPoint> CastLeg(const geometry::LegModel& leg,
                                      const geometry::Pose2& T_lidar_leg, double angle_increment) {
  return leg.shape == geometry::LegShape::kCircle
             ? CastCircle(T_lidar_leg.translation(), leg.Radius(), angle_increment)
             : CastBox(T_lidar_leg, leg.length_m, leg.width_m, angle_increment);
}

/// Adds a draw of `noise` to each point's range, keeping it on its beam.
template <typename Noise, typename Rng>
void AddRangeNoise(std::vector<ScanPoint>& points, Noise& noise, Rng& rng) {
  for (auto& q : points) {
    q.range += noise(rng);
    q.p = q.range * Eigen::Vector2d(std::cos(q.angle), std::sin(q.angle));
  }
}

}  // namespace shelfdock::perception::testing
