#include "docking/docking_config.hpp"

namespace shelfdock::docking {

std::optional<std::string> Validate(const DockingConfig& c) {
  auto positive = [](double v) { return v > 0.0; };
  struct Check {
    bool ok;
    const char* message;
  };
  const Check checks[] = {
      {positive(c.planner.final_straight_m), "planner.final_straight_m: must be > 0"},
      {c.planner.min_final_straight_m >= 0.0 &&
           c.planner.min_final_straight_m <= c.planner.final_straight_m,
       "planner.min_final_straight_m: must be in [0, final_straight_m]"},
      {positive(c.planner.max_curvature_1pm), "planner.max_curvature_1pm: must be > 0"},
      {positive(c.planner.sample_step_m), "planner.sample_step_m: must be > 0"},
      {positive(c.controller.max_speed_mps), "controller.max_speed_mps: must be > 0"},
      {positive(c.controller.approach_speed_mps), "controller.approach_speed_mps: must be > 0"},
      {positive(c.controller.max_accel_mps2), "controller.max_accel_mps2: must be > 0"},
      {positive(c.controller.max_decel_mps2), "controller.max_decel_mps2: must be > 0"},
      {positive(c.controller.max_yaw_rate_radps), "controller.max_yaw_rate_radps: must be > 0"},
      {positive(c.controller.max_lateral_accel_mps2),
       "controller.max_lateral_accel_mps2: must be > 0"},
      {positive(c.controller.lateral_settle_m), "controller.lateral_settle_m: must be > 0"},
      {positive(c.controller.approach_lateral_settle_m),
       "controller.approach_lateral_settle_m: must be > 0"},
      {positive(c.controller.creep_speed_mps) &&
           c.controller.creep_speed_mps < c.controller.max_speed_mps,
       "controller.creep_speed_mps: must be in (0, max_speed_mps)"},
      {positive(c.controller.goal_tolerance_m), "controller.goal_tolerance_m: must be > 0"},
      {c.controller.heading_priority_m >= 0.0, "controller.heading_priority_m: must be >= 0"},
      {positive(c.controller.heading_settle_m), "controller.heading_settle_m: must be > 0"},
      {positive(c.tracker.gate_xy_m), "tracker.gate_xy_m: must be > 0"},
      {positive(c.tracker.gate_yaw_rad), "tracker.gate_yaw_rad: must be > 0"},
      {c.tracker.reinit_after_rejects >= 1, "tracker.reinit_after_rejects: must be >= 1"},
      {positive(c.tracker.preset_gate_sigmas), "tracker.preset_gate_sigmas: must be > 0"},
      {positive(c.tracker.min_sigma_xy_m), "tracker.min_sigma_xy_m: must be > 0"},
      {positive(c.tracker.min_sigma_yaw_rad), "tracker.min_sigma_yaw_rad: must be > 0"},
      {positive(c.safety.robot_length_m), "safety.robot_length_m: must be > 0"},
      {positive(c.safety.robot_width_m), "safety.robot_width_m: must be > 0"},
      {c.safety.leg_margin_m >= 0.0, "safety.leg_margin_m: must be >= 0"},
      {c.verify.frames >= 1, "verify.frames: must be >= 1"},
      {c.camera_guide.frames >= 1, "camera_guide.frames: must be >= 1"},
      {c.camera_guide.camera_on_m >= 0.0, "camera_guide.camera_on_m: must be >= 0"},
      {c.camera_guide.min_remaining_m >= 0.0, "camera_guide.min_remaining_m: must be >= 0"},
      {positive(c.camera_guide.replan_xy_m), "camera_guide.replan_xy_m: must be > 0"},
      {positive(c.camera_guide.replan_yaw_rad), "camera_guide.replan_yaw_rad: must be > 0"},
      {positive(c.camera_guide.max_curvature_1pm), "camera_guide.max_curvature_1pm: must be > 0"},
      {c.verify.max_adjust_tries >= 0, "verify.max_adjust_tries: must be >= 0"},
      {positive(c.verify.tolerance_xy_m), "verify.tolerance_xy_m: must be > 0"},
      {positive(c.verify.tolerance_yaw_rad), "verify.tolerance_yaw_rad: must be > 0"},
      {c.verify.settle_s >= 0.0, "verify.settle_s: must be >= 0"},
      {c.verify.lateral_tolerance_m >= 0.0, "verify.lateral_tolerance_m: must be >= 0"},
      {c.verify.max_lever_angle_rad > 0.0 && c.verify.max_lever_angle_rad < 1.5,
       "verify.max_lever_angle_rad: must be in (0, 1.5)"},
      {positive(c.verify.adjust_speed_mps), "verify.adjust_speed_mps: must be > 0"},
      {positive(c.verify.adjust_accel_mps2), "verify.adjust_accel_mps2: must be > 0"},
      {positive(c.verify.adjust_yaw_rate_radps), "verify.adjust_yaw_rate_radps: must be > 0"},
      {positive(c.verify.adjust_yaw_accel_radps2), "verify.adjust_yaw_accel_radps2: must be > 0"},
      {c.baseline.standing_scans >= 1, "baseline.standing_scans: must be >= 1"},
      {c.baseline.parking_distance_m > c.planner.min_final_straight_m,
       "baseline.parking_distance_m: must exceed planner.min_final_straight_m"},
      {positive(c.entry_distance_m), "entry_distance_m: must be > 0"},
      {c.max_replans >= 0, "max_replans: must be >= 0"},
      {positive(c.min_entry_distance_m) && c.min_entry_distance_m <= c.entry_distance_m,
       "min_entry_distance_m: must be in (0, entry_distance_m]"},
      {c.entry_tolerance_m >= 0.0, "entry_tolerance_m: must be >= 0"},
      {positive(c.area_half_width_m), "area_half_width_m: must be > 0"},
      {positive(c.area_max_heading_rad), "area_max_heading_rad: must be > 0"},
      {c.turn_penalty_m >= 0.0, "turn_penalty_m: must be >= 0"},
      {c.max_move_out_m >= 0.0, "max_move_out_m: must be >= 0"},
      {c.max_approach_plans >= 1, "max_approach_plans: must be >= 1"},
      {c.max_block_replans >= 0, "max_block_replans: must be >= 0"},
      {c.abort_decel_factor >= 1.0, "abort_decel_factor: must be >= 1"},
      {positive(c.detection_lost_s), "detection_lost_s: must be > 0"},
      {positive(c.timeout_s), "timeout_s: must be > 0"},
      {positive(c.control_period_s), "control_period_s: must be > 0"},
  };
  for (const Check& check : checks) {
    if (!check.ok) return std::string(check.message);
  }
  return std::nullopt;
}

}  // namespace shelfdock::docking
