#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "docking/approach_planner.hpp"
#include "docking/docking_area.hpp"
#include "docking/docking_config.hpp"
#include "docking/fine_adjust.hpp"
#include "docking/free_space.hpp"
#include "docking/obstacle_returns.hpp"
#include "docking/odometry_buffer.hpp"
#include "docking/outcome.hpp"
#include "docking/path_tracker.hpp"
#include "docking/shelf_tracker.hpp"
#include "geometry/laser_scan.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detection.hpp"
#include "perception/marker_detector.hpp"

namespace shelfdock::docking {

/// Continuous docking (the paper's) or the stop-and-recognise baseline.
enum class Method { kContinuous, kStopAndRecognise };
std::string_view ToString(Method method);

/// What the robot is told: which shelf, where it should be, and which model it is.
struct DockingTask {
  int shelf_id = -1;
  geometry::Pose2 T_map_shelf_preset;
  geometry::ShelfModel model;  ///< the target's model (legs for the clearance check)
  /// What the map says is occupied (walls, racks, posts, the other shelves' legs), map frame;
  /// the target shelf is not in it. Empty: open space.
  FreeSpace map_obstacles;
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

/// The Docker's stage; ToString gives the record's name.
enum class Phase { kApproach, kDock, kStand, kVerify, kAdjust, kLift, kAbort, kDone };
std::string_view ToString(Phase phase);

/// What the Docker asks of the robot for one control step.
struct Command {
  VelocityCommand velocity;         ///< drive command
  bool camera_on = false;           ///< the upward camera should look for the code
  bool start_lift = false;          ///< raise the lift now
  std::vector<std::string> events;  ///< what happened this step, for the record
};

/// The detector as the Docker uses it: motion-compensated points (lidar frame, beam order),
/// the beam spacing, and the expected shelf pose in the lidar frame.
using DetectFn = std::function<perception::DetectionResult(
    const std::vector<perception::ScanPoint>&, double, const std::optional<geometry::Pose2>&)>;

/// The docking state machine (paper 3.5). Step() is called at the control rate with what the
/// robot sees and returns what it does; it never blocks and always ends (timeouts), in kDone
/// with an Outcome.
///   kApproach: choose the docking area from the free space (which end, how long a straight),
///              then get to its entry on the localisation estimate: a smooth curve, or turns on
///              the spot and straight moves (reversing out first when there is no room to turn).
///   kDock:     on odometry relative to the shelf; continuous method: detect every scan (motion
///              compensated), fuse, re-plan when the goal moves; stop using the LiDAR near the
///              legs. Baseline: drive to a parking spot, kStand, then dock blind.
///   kVerify:   read the code under the shelf; wrong id aborts; offset -> kAdjust (few tries).
///   kLift, kDone. kAbort brakes to a stop before kDone on any failure.
/// Each stage keeps its own state (ApproachState, DockState, ...); what they share (the shelf
/// estimate, the path being followed, the goal) lives in the Docker.
class Docker {
 public:
  Docker(DockingConfig config, DockingTask task, Method method, DetectFn detect);

  Command Step(const Observations& obs);

  Phase phase() const { return phase_; }
  bool done() const { return phase_ == Phase::kDone; }
  const Outcome& outcome() const { return outcome_; }
  double docking_start_time() const { return docking_start_t_; }  ///< NaN before the entry
  int replans() const { return dock_.replans; }
  int detections() const { return tracker_.detections(); }
  const Path& path() const { return follower_.path(); }
  int path_version() const { return path_version_; }
  bool path_in_odom() const { return phase_ != Phase::kApproach; }
  const std::optional<geometry::Pose2>& last_detection_odom() const { return dock_.last_detection; }
  const ShelfTracker& shelf_tracker() const { return tracker_; }
  /// The robot's offset from the goal measured by the last code check (goal frame).
  const std::optional<geometry::Pose2>& last_code_offset() const { return verify_.code_offset; }
  /// The LiDAR-guided goal (odom frame) as it was when the camera first corrected it while
  /// driving in; empty when the camera never corrected the goal.
  const std::optional<geometry::Pose2>& lidar_goal_before_camera() const {
    return guide_.lidar_goal_before_camera;
  }
  int camera_corrections() const { return guide_.corrections; }
  int code_checks() const { return verify_.code_checks; }   ///< standing code checks made
  int adjustments() const { return verify_.adjust_tries; }  ///< fine adjustments started
  /// The docking area chosen (valid once the approach is planned).
  const std::optional<DockingArea>& docking_area() const { return approach_.area; }
  /// How the approach was planned last (valid once planned).
  ApproachKind approach_kind() const { return approach_.plan.kind; }

 private:
  /// kApproach: the plan and where in it the robot is.
  struct ApproachState {
    enum class Step { kPlan, kFirstTurn, kFollow, kFinalTurn, kMoveOut };
    Step step = Step::kPlan;
    std::optional<DockingArea> area;
    FreeSpace free_space;  ///< the map's obstacles and the target's legs at the preset (map)
    ApproachPlan plan;
    int plans = 0;
    geometry::Pose2 T_odom_map;     ///< at planning time: manoeuvres run on odometry
    int replans_for_block = 0;      ///< blocked ways re-planned from a scan so far
    double blocked_since_t = -1.0;  ///< [s] a later block is waited out, up to a limit
  };
  /// kDock: recognition while moving, re-planning, obstacle stops.
  struct DockState {
    bool lidar_in_use = true;
    bool two_leg_tracking = false;  ///< only two legs trusted: re-measured, not detected
    bool goal_is_parking = false;
    std::optional<geometry::Pose2> last_detection;
    std::optional<geometry::Pose2> first_goal;  ///< the goal of the first plan (odom)
    geometry::Pose2 T_odom_shelf_preset;        ///< where the map says the shelf is
    double last_scan_t = 0.0;
    double last_detection_t = 0.0;
    double blocked_since_t = -1.0;
    bool lidar_silent = false;  ///< stopped: no scan for scan_timeout_s
    int replans = 0;
    std::string replan_failure;
  };
  /// kStand (baseline): recognition while standing at the parking spot.
  struct StandState {
    int scans = 0;
  };
  /// The camera in advance on the final straight (paper 3.5).
  struct GuideState {
    std::vector<geometry::Pose2> tags;  ///< T_odom_tag read while driving in
    std::optional<geometry::Pose2> lidar_goal_before_camera;
    int corrections = 0;
  };
  /// kVerify / kAdjust: the code check and the fine adjustment.
  struct VerifyState {
    std::vector<geometry::Pose2> readings;
    std::optional<geometry::Pose2> code_offset;
    int missing_frames = 0;
    int adjust_tries = 0;
    int code_checks = 0;
    bool lift_after_adjust = false;  ///< the check was made on the way in: lift after the turn
  };

  void Start(const Observations& obs, Command* cmd);
  void PlanApproachFrom(const Observations& obs, Command* cmd);
  void StepApproach(const Observations& obs, double dt, Command* cmd);
  bool ApproachStillClear(const Observations& obs) const;
  void StartDocking(const Observations& obs, Command* cmd);
  void StepDock(const Observations& obs, Command* cmd);
  void StepStand(const Observations& obs, Command* cmd);
  void StartVerify(double t_s, Command* cmd);
  void StartLift(double t_s, Command* cmd);
  void StepVerify(const Observations& obs, Command* cmd);
  void ProcessScan(const Observations& obs, bool recognise, Command* cmd);
  void GuideByCode(const Observations& obs, Command* cmd);
  bool StartAdjustFromGuide(const Observations& obs, Command* cmd);
  geometry::Pose2 TagGoal(const geometry::Pose2& T_tag_base) const;
  enum class PlanStatus { kOk, kInfeasible, kCollides };
  PlanStatus Replan(const geometry::Pose2& T_odom_base, const geometry::Pose2& goal, Command* cmd,
                    const PlannerConfig* planner = nullptr);
  bool ReplanJustified() const;
  // Moves the current path's end onto `goal` (BendPathToGoal) when the bent path stays within
  // `max_curvature_1pm` ahead of the robot and clear of the legs; false leaves the path as it was.
  bool BendToGoal(const geometry::Pose2& T_odom_base, const geometry::Pose2& goal,
                  double max_curvature_1pm, Command* cmd);
  /// Which of the shelf's legs the LiDAR can still be trusted on from here (range and bearing),
  /// on the fused estimate.
  std::array<bool, 4> TrustedLegs(const geometry::Pose2& T_odom_base) const;
  /// Fuses one measurement of the shelf (odom frame; covariance in the lidar frame) and re-plans
  /// when the goal moved (paper 3.5). `what` names it in the event.
  void FuseShelf(const Observations& obs, const geometry::Pose2& T_odom_shelf,
                 const geometry::Pose2& T_odom_lidar, const Eigen::Matrix3d& covariance_lidar,
                 const std::string& what, Command* cmd);
  geometry::Pose2 GoalFromShelf(const geometry::Pose2& T_odom_shelf) const;
  void Fail(OutcomeCode code, std::string reason, Command* cmd);
  VelocityCommand BrakeCommand(double dt) const;

  DockingConfig config_;
  DockingTask task_;
  Method method_;
  DetectFn detect_;
  Phase phase_ = Phase::kApproach;
  Outcome outcome_;

  // Shared by the stages.
  OdometryBuffer odometry_;
  PathTracker follower_;
  ShelfTracker tracker_;
  FineAdjust adjust_;     ///< the fine adjustment under the shelf
  FineAdjust manoeuvre_;  ///< turns and straight moves on the way to the docking area
  geometry::Pose2 T_odom_map_;
  geometry::Pose2 T_shelf_goal_;  ///< robot pose under the shelf (which end it enters from)
  geometry::Pose2 T_odom_goal_;   ///< the current path's end
  int path_version_ = 0;
  bool started_ = false;
  double t_start_ = 0.0;
  double docking_start_t_;
  double phase_start_t_ = 0.0;
  double last_t_ = 0.0;
  double last_v_cmd_ = 0.0;
  geometry::Pose2 last_T_odom_base_;
  /// The latest scan's returns in the odometry frame and which of them may be obstacles
  /// (ObstacleReturns, corroborated by a neighbouring beam or the scan before).
  ScanReturns scan_returns_;
  std::vector<char> obstacle_returns_;

  ApproachState approach_;
  DockState dock_;
  StandState stand_;
  GuideState guide_;
  VerifyState verify_;
};

}  // namespace shelfdock::docking
