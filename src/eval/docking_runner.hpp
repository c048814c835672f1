#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "docking/docker.hpp"
#include "docking/docking_config.hpp"
#include "docking/path.hpp"
#include "eval/fault.hpp"
#include "perception/detector_config.hpp"
#include "perception/marker_detector.hpp"
#include "sim/diff_drive_robot.hpp"
#include "sim/lidar_config.hpp"
#include "sim/marker_camera.hpp"
#include "sim/scenario.hpp"
#include "sim/sensor_rig.hpp"

namespace shelfdock::eval {

/// Everything a closed-loop docking run needs besides the scenario.
struct RunConfig {
  docking::DockingConfig docking;
  sim::DiffDriveConfig robot;
  sim::LidarConfig lidar;
  sim::CameraConfig camera;
  perception::DetectorConfig detector;
  perception::MarkerDetectorConfig marker;
  sim::SensorRigConfig sensors;   ///< sensor timing and injected failures
  double max_sim_time_s = 120.0;  ///< [s] hard stop of the simulation loop
  bool record = false;            ///< keep one RecordFrame per control step
  /// Keep every detection accepted after the docking area's entry and the fused estimate after
  /// it (DockingRun::recognitions).
  bool keep_recognitions = false;
  /// Start here instead of the scenario's robot_start (a start-anywhere sweep).
  std::optional<geometry::Pose2> T_map_robot_start;
  /// A fault injected between the sensors and the Docker (eval faults); its changes to the world
  /// are the caller's (ApplyFaultToScenario). kNone: no fault.
  FaultSpec fault;
};

/// The robot's final pose against the TRUE shelf centre in the shelf's goal frame.
struct PoseError {
  double x = 0.0, y = 0.0, yaw = 0.0;  ///< [m, m, rad]
  bool valid = false;                  ///< false when that stage was never reached
};

/// One control step, for replay. Poses in the world (= map) frame. Things the robot keeps in
/// its odometry frame (detections, fused shelf, path) are drawn where the robot believes them,
/// i.e. mapped with the TRUE T_world_odom of that instant.
struct RecordFrame {
  double t_s = 0.0;
  std::string phase;
  geometry::Pose2 T_world_base_true;
  geometry::Pose2 T_odom_base;
  geometry::Pose2 T_map_base_estimate;
  double v_cmd = 0.0, w_cmd = 0.0;
  std::vector<Eigen::Vector2d> scan_world;  ///< this step's scan (true pose), empty if none
  std::optional<geometry::Pose2> detection_world;
  std::optional<geometry::Pose2> shelf_estimate_world;
  std::vector<geometry::Pose2> path_world;  ///< only when the path changed this step
  std::vector<std::string> events;
};

/// Where the time of one run went, per Docker phase (seconds of simulated time). The sum of all
/// but `approach_s` is DockingRun::time_s.
struct PhaseTimes {
  double approach_s = 0.0;    ///< [s] to the docking area's entry (not part of time_s)
  double dock_s = 0.0;        ///< [s] driving in the docking area (both legs for the baseline)
  double final_slow_s = 0.0;  ///< [s] part of dock_s below 0.1 m/s: the final stop(s)
  double stand_s = 0.0;       ///< [s] baseline: standing at the parking spot to recognise
  double verify_s = 0.0;      ///< [s] code checks (camera frames), all tries
  double adjust_s = 0.0;      ///< [s] fine adjustments, all tries
  double lift_s = 0.0;        ///< [s]
  double abort_s = 0.0;       ///< [s] braking after a failure
  int code_checks = 0;        ///< code checks made (1 + adjustments that were re-checked)
  int adjustments = 0;        ///< fine adjustments made
};

/// One accepted detection during a run and the fused shelf estimate right after it, placed in
/// the world with the TRUE robot pose of that instant (the recognition's own error, as a robot
/// with perfect localisation would map it) and in the map with the robot's own localisation
/// estimate (what the paper's Fig. 7 plots: "project this result ... onto the map").
struct Recognition {
  double t_s = 0.0;  ///< [s] simulated time
  geometry::Pose2 T_world_shelf_detected;
  geometry::Pose2 T_world_shelf_fused;
  geometry::Pose2 T_map_shelf_detected;
  geometry::Pose2 T_map_shelf_fused;
};

/// One simulated docking: its outcome and measured errors and times.
struct DockingRun {
  docking::Outcome outcome;
  docking::Method method = docking::Method::kContinuous;
  std::uint64_t seed = 0;
  /// [s] docking area entry to end of lift (or to the stop on failure). The clock starts when
  /// the robot truly crosses the entry (entry distance behind the true goal, within the area's
  /// width), not when the Docker believes it did: its localisation bias (up to ~3 cm along the
  /// axis) would otherwise move the start by up to ~0.1 s either way at the docking speed.
  double time_s = 0.0;
  /// LiDAR-guided final error (the "before the code check"): where the LiDAR-guided
  /// goal truly lay when the camera first corrected it on the way in, else the pose at the stop.
  PoseError error_before_check;
  PoseError error_after_check;  ///< the pose when the lift starts
  int replans = 0;
  int detections = 0;
  double min_leg_clearance_m = 1e9;  ///< [m] true footprint to true legs over the whole run
  /// The Docker had not ended when max_sim_time_s came (a hang; outcome kTimeout).
  bool hung = false;
  PhaseTimes phases;
  std::vector<RecordFrame> record;
  std::vector<Recognition> recognitions;  ///< only with RunConfig::keep_recognitions
};

/// Runs one docking in the simulator: world, LiDAR (motion-skewed scans), robot (limits,
/// odometry, localisation), upward camera and code detector around a docking::Docker that sees
/// only the robot's sensors. The target shelf, its model and preset come from the scenario.
DockingRun RunDocking(const sim::Scenario& scenario,
                      const std::vector<geometry::ShelfModel>& models, docking::Method method,
                      std::uint64_t seed, const RunConfig& config);

/// Docking time of a robot that knows the true shelf pose, on DockingRun::time_s's definition:
/// from crossing the docking area's entry (reached at the docking speed after the same approach)
/// to the end of the lift; one plan to the true goal with the same limits, no detection, no code
/// check.
double PerfectKnowledgeTime(const sim::Scenario& scenario, const RunConfig& config);

/// Distance between the robot's footprint at T_world_base and a leg (negative: overlap).
double FootprintLegDistance(const geometry::Pose2& T_world_base, double length_m, double width_m,
                            const sim::LegFootprint& leg);

}  // namespace shelfdock::eval
