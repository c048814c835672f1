#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <random>

#include "docking/docker.hpp"
#include "eval/fault.hpp"
#include "geometry/laser_scan.hpp"
#include "sim/scenario.hpp"
#include "sim/sensor_rig.hpp"

namespace shelfdock::eval {

/// Puts a fault's changes to the world into the scenario: a person or robot crossing the
/// docking path, a person standing in it, the target shelf displaced, carrying another code, or
/// gone. The docking path is the line from the target's map pose along its long side toward the
/// robot's start (where the Docker enters). Other kinds leave the scenario as it is.
void ApplyFaultToScenario(const FaultSpec& fault, double docking_length_m, sim::Scenario* scenario);

/// Applies a fault to what the robot receives each control step (between the simulated sensors
/// and the Docker): LiDAR blackouts, spurious returns, late or doubled scans, odometry slip,
/// localisation jumps, a partly covered code. Blind cameras and blackouts use the sensor rig's
/// own injection (see ConfigureSensors).
class FaultInjector {
 public:
  FaultInjector(FaultSpec fault, std::uint64_t seed);

  /// Sets the sensor rig's own failure switches for this fault.
  void ConfigureSensors(sim::SensorRigConfig* sensors) const;

  /// Rewrites one step's readings (before the code detector sees the image) and the odometry and
  /// localisation in `obs`. `since_entry_s` is NaN before the docking area's entry.
  /// readings->scan may afterwards point into this injector (valid until the next call).
  void Apply(double t_s, double since_entry_s, sim::SensorReadings* readings,
             docking::Observations* obs);

 private:
  bool Active(double since_entry_s) const;
  void Spurious(geometry::LaserScan* scan);
  void SlipOdometry(bool slipping, docking::Observations* obs);
  void CoverCode(geometry::GrayImage* image);

  FaultSpec fault_;
  std::mt19937_64 rng_;
  struct Pending {
    double due_s;
    geometry::LaserScan scan;
  };
  std::deque<Pending> pending_;  ///< late or repeated scans waiting to be delivered
  geometry::LaserScan delivered_;
  // Odometry as reported: the true increments, scaled while the wheels slip.
  std::optional<geometry::Pose2> last_true_odom_;
  geometry::Pose2 reported_odom_;
};

}  // namespace shelfdock::eval
