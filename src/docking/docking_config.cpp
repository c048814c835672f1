#include "docking/docking_config.hpp"

#include <cmath>
#include <numbers>

namespace shelfdock::docking {
namespace {

using geometry::ConfigChecker;
constexpr double kPi = std::numbers::pi;

bool Positive(double v) { return v > 0.0; }
bool NonNegative(double v) { return v >= 0.0; }

}  // namespace

std::optional<ConfigViolation> FindConfigViolation(const PlannerConfig& c) {
  ConfigChecker k;
  k.Check(Positive(c.final_straight_m), "final_straight_m", "> 0");
  k.Check(c.min_final_straight_m >= 0.0 && c.min_final_straight_m <= c.final_straight_m,
          "min_final_straight_m", "in [0, final_straight_m]");
  k.Check(Positive(c.max_curvature_1pm), "max_curvature_1pm", "> 0");
  k.Check(Positive(c.sample_step_m), "sample_step_m", "> 0");
  return k.Result();
}

std::optional<ConfigViolation> FindConfigViolation(const ControllerConfig& c) {
  ConfigChecker k;
  k.Check(Positive(c.max_speed_mps), "max_speed_mps", "> 0");
  k.Check(Positive(c.approach_speed_mps), "approach_speed_mps", "> 0");
  k.Check(Positive(c.max_accel_mps2), "max_accel_mps2", "> 0");
  k.Check(Positive(c.max_decel_mps2), "max_decel_mps2", "> 0");
  k.Check(Positive(c.max_yaw_rate_radps), "max_yaw_rate_radps", "> 0");
  k.Check(Positive(c.max_lateral_accel_mps2), "max_lateral_accel_mps2", "> 0");
  k.Check(Positive(c.lateral_settle_m), "lateral_settle_m", "> 0");
  k.Check(Positive(c.approach_lateral_settle_m), "approach_lateral_settle_m", "> 0");
  k.Check(Positive(c.creep_speed_mps) && c.creep_speed_mps < c.max_speed_mps, "creep_speed_mps",
          "in (0, max_speed_mps)");
  k.Check(Positive(c.goal_tolerance_m), "goal_tolerance_m", "> 0");
  k.Check(Positive(c.max_cross_track_m), "max_cross_track_m", "> 0");
  k.Check(NonNegative(c.heading_priority_m), "heading_priority_m", ">= 0");
  k.Check(Positive(c.heading_settle_m), "heading_settle_m", "> 0");
  return k.Result();
}

std::optional<ConfigViolation> FindConfigViolation(const ShelfTrackerConfig& c) {
  ConfigChecker k;
  k.Check(Positive(c.gate_xy_m), "gate_xy_m", "> 0");
  k.Check(Positive(c.gate_yaw_rad), "gate_yaw_rad", "> 0");
  k.Check(c.reinit_after_rejects >= 1, "reinit_after_rejects", ">= 1");
  k.Check(Positive(c.min_sigma_xy_m), "min_sigma_xy_m", "> 0");
  k.Check(Positive(c.min_sigma_yaw_rad), "min_sigma_yaw_rad", "> 0");
  k.Check(NonNegative(c.drift_sigma_xy_per_m), "drift_sigma_xy_per_m", ">= 0");
  k.Check(NonNegative(c.drift_sigma_yaw_per_m), "drift_sigma_yaw_per_m", ">= 0");
  k.Check(NonNegative(c.drift_rate_sigma_yaw_per_m), "drift_rate_sigma_yaw_per_m", ">= 0");
  k.Check(Positive(c.preset_sigma_xy_m), "preset_sigma_xy_m", "> 0");
  k.Check(Positive(c.preset_sigma_yaw_rad), "preset_sigma_yaw_rad", "> 0");
  k.Check(Positive(c.preset_gate_sigmas), "preset_gate_sigmas", "> 0");
  return k.Result();
}

std::optional<ConfigViolation> FindConfigViolation(const SafetyConfig& c) {
  ConfigChecker k;
  k.Check(Positive(c.robot_length_m), "robot_length_m", "> 0");
  k.Check(Positive(c.robot_width_m), "robot_width_m", "> 0");
  k.Check(std::abs(c.robot_offset_x_m) < 0.5 * c.robot_length_m, "robot_offset_x_m",
          "within half the robot's length of the base");
  k.Check(NonNegative(c.leg_margin_m), "leg_margin_m", ">= 0");
  k.Check(NonNegative(c.obstacle_margin_m), "obstacle_margin_m", ">= 0");
  k.Check(Positive(c.obstacle_lookahead_m), "obstacle_lookahead_m", "> 0");
  k.Check(NonNegative(c.obstacle_wait_s), "obstacle_wait_s", ">= 0");
  k.Check(NonNegative(c.obstacle_neighbour_gap_m), "obstacle_neighbour_gap_m", ">= 0 (0: off)");
  k.Check(NonNegative(c.leg_exclusion_m), "leg_exclusion_m", ">= 0");
  return k.Result();
}

std::optional<ConfigViolation> FindConfigViolation(const VerifyConfig& c) {
  ConfigChecker k;
  k.Check(c.frames >= 1, "frames", ">= 1");
  k.Check(c.max_missing_frames >= 1, "max_missing_frames", ">= 1");
  k.Check(NonNegative(c.settle_s), "settle_s", ">= 0");
  k.Check(Positive(c.tolerance_xy_m), "tolerance_xy_m", "> 0");
  k.Check(Positive(c.tolerance_yaw_rad), "tolerance_yaw_rad", "> 0");
  k.Check(c.max_adjust_tries >= 0, "max_adjust_tries", ">= 0");
  k.Check(NonNegative(c.lateral_tolerance_m), "lateral_tolerance_m", ">= 0");
  k.Check(c.max_lever_angle_rad > 0.0 && c.max_lever_angle_rad < 1.5, "max_lever_angle_rad",
          "in (0, 1.5)");
  k.Check(Positive(c.adjust_speed_mps), "adjust_speed_mps", "> 0");
  k.Check(Positive(c.adjust_accel_mps2), "adjust_accel_mps2", "> 0");
  k.Check(Positive(c.adjust_yaw_rate_radps), "adjust_yaw_rate_radps", "> 0");
  k.Check(Positive(c.adjust_yaw_accel_radps2), "adjust_yaw_accel_radps2", "> 0");
  k.Check(Positive(c.max_correction_m), "max_correction_m", "> 0");
  return k.Result();  // check_on_the_way_in: either value
}

std::optional<ConfigViolation> FindConfigViolation(const CameraGuideConfig& c) {
  ConfigChecker k;  // enabled: either value
  k.Check(NonNegative(c.camera_on_m), "camera_on_m", ">= 0");
  k.Check(c.frames >= 1, "frames", ">= 1");
  k.Check(NonNegative(c.min_remaining_m), "min_remaining_m", ">= 0");
  k.Check(Positive(c.correct_xy_m), "correct_xy_m", "> 0");
  k.Check(Positive(c.correct_yaw_rad), "correct_yaw_rad", "> 0");
  k.Check(Positive(c.max_curvature_1pm), "max_curvature_1pm", "> 0");
  return k.Result();
}

std::optional<ConfigViolation> FindConfigViolation(const BaselineConfig& c) {
  ConfigChecker k;
  k.Check(Positive(c.parking_distance_m), "parking_distance_m", "> 0");
  k.Check(NonNegative(c.settle_s), "settle_s", ">= 0");
  k.Check(c.standing_scans >= 1, "standing_scans", ">= 1");
  return k.Result();
}

std::optional<ConfigViolation> FindConfigViolation(const DockingConfig& c) {
  ConfigChecker k;
  k.Nested("planner", FindConfigViolation(c.planner));
  k.Nested("controller", FindConfigViolation(c.controller));
  k.Nested("tracker", FindConfigViolation(c.tracker));
  k.Nested("safety", FindConfigViolation(c.safety));
  k.Nested("verify", FindConfigViolation(c.verify));
  k.Nested("camera_guide", FindConfigViolation(c.camera_guide));
  k.Nested("baseline", FindConfigViolation(c.baseline));
  // Across structs: the baseline's parking spot needs a straight before the goal.
  k.Check(c.baseline.parking_distance_m > c.planner.min_final_straight_m,
          "baseline.parking_distance_m", "> planner.min_final_straight_m");
  // The LiDAR's mounting: x and y any finite value (the loader rejects others).
  k.Check(std::abs(c.T_base_lidar.yaw) <= kPi, "lidar_mount.yaw", "in [-pi, pi]");
  k.Check(std::abs(c.dock_yaw_offset_rad) <= kPi, "dock_yaw_offset_rad", "in [-pi, pi]");
  k.Check(Positive(c.entry_distance_m), "entry_distance_m", "> 0");
  k.Check(Positive(c.min_entry_distance_m) && c.min_entry_distance_m <= c.entry_distance_m,
          "min_entry_distance_m", "in (0, entry_distance_m]");
  k.Check(NonNegative(c.entry_tolerance_m), "entry_tolerance_m", ">= 0");
  k.Check(Positive(c.area_half_width_m), "area_half_width_m", "> 0");
  k.Check(Positive(c.area_max_heading_rad), "area_max_heading_rad", "> 0");
  k.Check(NonNegative(c.turn_penalty_m), "turn_penalty_m", ">= 0");
  k.Check(NonNegative(c.max_move_out_m), "max_move_out_m", ">= 0");
  k.Check(c.max_block_replans >= 0, "max_block_replans", ">= 0");
  k.Check(c.max_approach_plans >= 1, "max_approach_plans", ">= 1");
  // Both divide the goal's net movement in ReplanJustified.
  k.Check(Positive(c.replan_xy_m), "replan_xy_m", "> 0");
  k.Check(Positive(c.replan_yaw_rad), "replan_yaw_rad", "> 0");
  k.Check(c.max_replans >= 0, "max_replans", ">= 0");
  k.Check(NonNegative(c.lidar_cutoff_m), "lidar_cutoff_m", ">= 0");
  k.Check(NonNegative(c.leg_min_range_m), "leg_min_range_m", ">= 0");
  k.Check(c.leg_max_bearing_rad > 0.0 && c.leg_max_bearing_rad <= kPi, "leg_max_bearing_rad",
          "in (0, pi]");
  // The shelf must be found while some of the shortest docking area is still ahead.
  k.Check(NonNegative(c.must_detect_by_m) && c.must_detect_by_m < c.min_entry_distance_m,
          "must_detect_by_m", "in [0, min_entry_distance_m)");
  k.Check(Positive(c.detection_lost_s), "detection_lost_s", "> 0");
  // A silent LiDAR stops the robot before it counts as dead (detection_lost_s).
  k.Check(Positive(c.scan_timeout_s) && c.scan_timeout_s <= c.detection_lost_s, "scan_timeout_s",
          "in (0, detection_lost_s]");
  k.Check(Positive(c.lift_timeout_s), "lift_timeout_s", "> 0");
  k.Check(Positive(c.timeout_s), "timeout_s", "> 0");
  k.Check(Positive(c.control_period_s), "control_period_s", "> 0");
  k.Check(c.abort_decel_factor >= 1.0, "abort_decel_factor", ">= 1");
  return k.Result();
}

}  // namespace shelfdock::docking
