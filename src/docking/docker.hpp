#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "docking/docking_config.hpp"
#include "docking/fine_adjust.hpp"
#include "docking/odometry_buffer.hpp"
#include "docking/outcome.hpp"
#include "docking/path_tracker.hpp"
#include "docking/shelf_tracker.hpp"
#include "geometry/laser_scan.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detection.hpp"
#include "perception/marker_detector.hpp"

namespace shelfdock::docking {

enum class Method { kContinuous, kStopAndRecognise };
std::string_view ToString(Method method);

/// What the robot is told: which shelf, where it should be, and which model it is.
struct DockingTask {
  int shelf_id = -1;
  geometry::Pose2 T_map_shelf_preset;
  geometry::ShelfModel model;  ///< the target's model (legs for the clearance check)
};

/// Everything a real robot sees in one control step, and nothing more.
struct Observations {
  double t_s = 0.0;
  geometry::Pose2 T_odom_base;                ///< wheel odometry
  geometry::Pose2 T_map_base_estimate;        ///< localisation (laser SLAM on a real robot)
  const geometry::LaserScan* scan = nullptr;  ///< a scan completed since the last step, if any
  bool camera_frame = false;  ///< the camera delivered a frame this step (marker may be empty)
  std::optional<perception::MarkerObservation> marker;
  bool lift_done = false;
};

enum class Phase { kApproach, kDock, kStand, kVerify, kAdjust, kLift, kAbort, kDone };
std::string_view ToString(Phase phase);

struct Command {
  VelocityCommand velocity;
  bool camera_on = false;
  bool start_lift = false;
  std::vector<std::string> events;  ///< what happened this step, for the record
};

/// The detector as the Docker uses it: motion-compensated points (lidar frame, beam order),
/// the beam spacing, and the expected shelf pose in the lidar frame.
using DetectFn = std::function<perception::DetectionResult(
    const std::vector<perception::ScanPoint>&, double, const std::optional<geometry::Pose2>&)>;

/// The docking state machine (paper 3.5). Step() is called at the control rate with what the
/// robot sees and returns what it does; it never blocks and always ends (timeouts), in kDone
/// with an Outcome.
///   kApproach: follow a path to the docking area's entry on the localisation estimate.
///   kDock:     on odometry relative to the shelf; continuous method: detect every scan (motion
///              compensated), fuse, re-plan when the goal moves; stop using the LiDAR near the
///              legs. Baseline: drive to a parking spot, kStand, then dock blind.
///   kVerify:   read the code under the shelf; wrong id aborts; offset -> kAdjust (few tries).
///   kLift, kDone. kAbort brakes to a stop before kDone on any failure.
class Docker {
 public:
  Docker(DockingConfig config, DockingTask task, Method method, DetectFn detect);

  Command Step(const Observations& obs);

  Phase phase() const { return phase_; }
  bool done() const { return phase_ == Phase::kDone; }
  const Outcome& outcome() const { return outcome_; }
  double docking_start_time() const { return docking_start_t_; }  ///< NaN before the entry
  int replans() const { return replans_; }
  int detections() const { return tracker_.detections(); }
  const Path& path() const { return follower_.path(); }
  int path_version() const { return path_version_; }
  bool path_in_odom() const { return phase_ != Phase::kApproach; }
  const std::optional<geometry::Pose2>& last_detection_odom() const { return last_detection_; }
  const ShelfTracker& shelf_tracker() const { return tracker_; }
  /// The robot's offset from the goal measured by the last code check (goal frame).
  const std::optional<geometry::Pose2>& last_code_offset() const { return code_offset_; }
  /// The LiDAR-guided goal (odom frame) as it was when the camera first corrected it while
  /// driving in; empty when the camera never corrected the goal.
  const std::optional<geometry::Pose2>& lidar_goal_before_camera() const {
    return lidar_goal_before_camera_;
  }
  int camera_corrections() const { return camera_corrections_; }

 private:
  void StartDocking(const Observations& obs, Command* cmd);
  void StepDock(const Observations& obs, Command* cmd);
  void StepStand(const Observations& obs, Command* cmd);
  void StepVerify(const Observations& obs, Command* cmd);
  void ProcessScan(const Observations& obs, bool recognise, Command* cmd);
  void GuideByCode(const Observations& obs, Command* cmd);
  bool StartAdjustFromGuide(const Observations& obs, Command* cmd);
  geometry::Pose2 TagGoal(const geometry::Pose2& T_tag_base) const;
  enum class PlanStatus { kOk, kInfeasible, kCollides };
  PlanStatus Replan(const geometry::Pose2& T_odom_base, const geometry::Pose2& goal, Command* cmd,
                    const PlannerConfig* planner = nullptr);
  bool LidarStillUseful(const geometry::Pose2& T_odom_base) const;
  geometry::Pose2 GoalFromShelf(const geometry::Pose2& T_odom_shelf) const;
  void Fail(OutcomeCode code, std::string reason, Command* cmd);
  bool PlanApproach(const geometry::Pose2& T_map_base, const geometry::Pose2& T_map_entry);
  void StepApproach(const Observations& obs, double dt, Command* cmd);

  DockingConfig config_;
  DockingTask task_;
  Method method_;
  DetectFn detect_;
  Phase phase_ = Phase::kApproach;
  Outcome outcome_;

  OdometryBuffer odometry_;
  PathTracker follower_;
  ShelfTracker tracker_;
  FineAdjust adjust_;
  geometry::Pose2 T_odom_map_;
  geometry::Pose2 T_shelf_goal_;  ///< robot pose under the shelf (which end it entered from)
  geometry::Pose2 T_odom_goal_;   ///< the current path's end
  bool goal_is_parking_ = false;
  /// The approach's smooth curve was infeasible from where the robot stood: turn on the spot
  /// toward the entry first, then plan again.
  std::optional<geometry::Pose2> turn_toward_entry_;
  bool lidar_in_use_ = true;
  bool started_ = false;
  std::optional<geometry::Pose2> last_detection_;
  std::optional<geometry::Pose2> code_offset_;
  std::vector<geometry::Pose2> code_readings_;
  std::vector<geometry::Pose2> guide_tags_;  ///< T_odom_tag from the camera while driving in
  std::optional<geometry::Pose2> lidar_goal_before_camera_;
  int camera_corrections_ = 0;
  int path_version_ = 0;
  int replans_ = 0;
  int adjust_tries_ = 0;
  int missing_frames_ = 0;
  int standing_scans_ = 0;
  double t_start_ = 0.0;
  double docking_start_t_;
  double last_scan_t_ = 0.0;
  double last_detection_t_ = 0.0;
  double phase_start_t_ = 0.0;
  double blocked_since_t_ = -1.0;
  double last_t_ = 0.0;
  double last_v_cmd_ = 0.0;
  std::string replan_failure_;
  geometry::Pose2 last_T_odom_base_;
};

}  // namespace shelfdock::docking
