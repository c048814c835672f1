#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "sim/lidar_config.hpp"
#include "sim/world.hpp"

namespace shelfdock::sim {

/// What each beam really hit, for scoring and tests (not something a real sensor reports).
struct BeamTruth {
  ObjectKind kind = ObjectKind::kWall;
  int object_id = -1;  ///< shelf id for legs; -1 when nothing was hit
  int part = 0;        ///< leg index for shelf legs and people's legs (as Primitive::part)
  double true_range_m = std::numeric_limits<double>::quiet_NaN();  ///< [m] centre ray, exact
  bool mixed = false;  ///< the footprint straddled a depth edge
  bool stray = false;  ///< the range is a stray echo from nothing in the world
};

/// A simulated scan and, per beam, what it hit (for ground truth and tests).
struct LabelledScan {
  geometry::LaserScan scan;
  std::vector<BeamTruth> truth;  ///< one per beam
};

/// A simulated 2D LiDAR: ray casts a World beam by beam, then applies the flaws switched on in
/// its LidarConfig. Deterministic: the same seed and the same calls give the same scans.
class Lidar {
 public:
  using PoseAt = std::function<geometry::Pose2(double t_s)>;

  /// `config` must pass FindConfigViolation() (asserted).
  Lidar(LidarConfig config, std::uint64_t seed);

  /// A scan from a LiDAR standing still at T_world_lidar; moving obstacles still move
  /// during the scan. stamp = t0_s, beam i fires at t0_s + i * time_increment.
  geometry::LaserScan Scan(const World& world, const geometry::Pose2& T_world_lidar,
                           double t0_s = 0.0);
  /// A scan from a moving LiDAR: each beam is fired from T_world_lidar_at(its firing time), so
  /// the scan is skewed by the motion during the sweep as on a real robot.
  geometry::LaserScan Scan(const World& world, const PoseAt& T_world_lidar_at, double t0_s);
  LabelledScan ScanLabelled(const World& world, const PoseAt& T_world_lidar_at, double t0_s);

  const LidarConfig& config() const { return config_; }

 private:
  struct Echo;
  Echo CastBeam(const World& world, const geometry::Pose2& T_world_lidar, double beam_angle_rad,
                const std::vector<Primitive>& moving, bool footprint) const;

  LidarConfig config_;
  std::mt19937_64 rng_;
  std::vector<Primitive> moving_;  ///< scratch for moving obstacles at a beam's time
};

}  // namespace shelfdock::sim
