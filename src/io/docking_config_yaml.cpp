#include "io/docking_config_yaml.hpp"

#include "io/yaml_fields.hpp"

namespace shelfdock::io {

docking::DockingConfig ReadDockingConfig(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  docking::DockingConfig c;
  YamlFields top(root, path, "");
  {
    YamlFields f(top.Child("planner"), path, "planner");
    f.Read("final_straight_m", c.planner.final_straight_m);
    f.Read("min_final_straight_m", c.planner.min_final_straight_m);
    f.Read("max_curvature_1pm", c.planner.max_curvature_1pm);
    f.Read("sample_step_m", c.planner.sample_step_m);
    f.RejectUnknown();
  }
  {
    YamlFields f(top.Child("controller"), path, "controller");
    auto& k = c.controller;
    f.Read("max_speed_mps", k.max_speed_mps);
    f.Read("approach_speed_mps", k.approach_speed_mps);
    f.Read("max_accel_mps2", k.max_accel_mps2);
    f.Read("max_decel_mps2", k.max_decel_mps2);
    f.Read("max_yaw_rate_radps", k.max_yaw_rate_radps);
    f.Read("max_lateral_accel_mps2", k.max_lateral_accel_mps2);
    f.Read("lateral_settle_m", k.lateral_settle_m);
    f.Read("approach_lateral_settle_m", k.approach_lateral_settle_m);
    f.Read("creep_speed_mps", k.creep_speed_mps);
    f.Read("goal_tolerance_m", k.goal_tolerance_m);
    f.Read("max_cross_track_m", k.max_cross_track_m);
    f.Read("heading_priority_m", k.heading_priority_m);
    f.Read("heading_settle_m", k.heading_settle_m);
    f.RejectUnknown();
  }
  {
    YamlFields f(top.Child("tracker"), path, "tracker");
    auto& k = c.tracker;
    f.Read("gate_xy_m", k.gate_xy_m);
    f.Read("gate_yaw_rad", k.gate_yaw_rad);
    f.Read("reinit_after_rejects", k.reinit_after_rejects);
    f.Read("min_sigma_xy_m", k.min_sigma_xy_m);
    f.Read("min_sigma_yaw_rad", k.min_sigma_yaw_rad);
    f.Read("drift_sigma_xy_per_m", k.drift_sigma_xy_per_m);
    f.Read("drift_sigma_yaw_per_m", k.drift_sigma_yaw_per_m);
    f.Read("drift_rate_sigma_yaw_per_m", k.drift_rate_sigma_yaw_per_m);
    f.Read("preset_sigma_xy_m", k.preset_sigma_xy_m);
    f.Read("preset_sigma_yaw_rad", k.preset_sigma_yaw_rad);
    f.Read("preset_gate_sigmas", k.preset_gate_sigmas);
    f.RejectUnknown();
  }
  {
    YamlFields f(top.Child("safety"), path, "safety");
    auto& k = c.safety;
    f.Read("leg_margin_m", k.leg_margin_m);
    f.Read("obstacle_margin_m", k.obstacle_margin_m);
    f.Read("obstacle_lookahead_m", k.obstacle_lookahead_m);
    f.Read("obstacle_wait_s", k.obstacle_wait_s);
    f.Read("obstacle_neighbour_gap_m", k.obstacle_neighbour_gap_m);
    f.Read("leg_exclusion_m", k.leg_exclusion_m);
    f.RejectUnknown();
  }
  {
    YamlFields f(top.Child("verify"), path, "verify");
    auto& k = c.verify;
    f.Read("frames", k.frames);
    f.Read("max_missing_frames", k.max_missing_frames);
    f.Read("tolerance_xy_m", k.tolerance_xy_m);
    f.Read("tolerance_yaw_rad", k.tolerance_yaw_rad);
    f.Read("max_adjust_tries", k.max_adjust_tries);
    f.Read("settle_s", k.settle_s);
    f.Read("lateral_tolerance_m", k.lateral_tolerance_m);
    f.Read("max_lever_angle_rad", k.max_lever_angle_rad);
    f.Read("adjust_speed_mps", k.adjust_speed_mps);
    f.Read("adjust_accel_mps2", k.adjust_accel_mps2);
    f.Read("adjust_yaw_rate_radps", k.adjust_yaw_rate_radps);
    f.Read("adjust_yaw_accel_radps2", k.adjust_yaw_accel_radps2);
    f.Read("max_correction_m", k.max_correction_m);
    f.Read("check_on_the_way_in", k.check_on_the_way_in);
    f.RejectUnknown();
  }
  {
    YamlFields f(top.Child("camera_guide"), path, "camera_guide");
    auto& k = c.camera_guide;
    f.Read("enabled", k.enabled);
    f.Read("camera_on_m", k.camera_on_m);
    f.Read("frames", k.frames);
    f.Read("min_remaining_m", k.min_remaining_m);
    f.Read("correct_xy_m", k.correct_xy_m);
    f.Read("correct_yaw_rad", k.correct_yaw_rad);
    f.Read("max_curvature_1pm", k.max_curvature_1pm);
    // Renamed (the top-level replan_xy_m is the LiDAR's threshold, a different thing).
    f.Renamed("replan_xy_m", "camera_guide.correct_xy_m");
    f.Renamed("replan_yaw_rad", "camera_guide.correct_yaw_rad");
    f.RejectUnknown();
  }
  {
    YamlFields f(top.Child("baseline"), path, "baseline");
    f.Read("parking_distance_m", c.baseline.parking_distance_m);
    f.Read("settle_s", c.baseline.settle_s);
    f.Read("standing_scans", c.baseline.standing_scans);
    f.RejectUnknown();
  }
  {
    YamlFields f(top.Child("lidar_mount"), path, "lidar_mount");
    f.Read("x", c.T_base_lidar.x);
    f.Read("y", c.T_base_lidar.y);
    f.Read("yaw", c.T_base_lidar.yaw);
    f.RejectUnknown();
  }
  top.Read("dock_yaw_offset_rad", c.dock_yaw_offset_rad);
  top.Read("entry_distance_m", c.entry_distance_m);
  top.Read("replan_xy_m", c.replan_xy_m);
  top.Read("replan_yaw_rad", c.replan_yaw_rad);
  top.Read("max_replans", c.max_replans);
  top.Read("min_entry_distance_m", c.min_entry_distance_m);
  top.Read("entry_tolerance_m", c.entry_tolerance_m);
  top.Read("area_half_width_m", c.area_half_width_m);
  top.Read("area_max_heading_rad", c.area_max_heading_rad);
  top.Read("turn_penalty_m", c.turn_penalty_m);
  top.Read("max_move_out_m", c.max_move_out_m);
  top.Read("max_approach_plans", c.max_approach_plans);
  top.Read("max_block_replans", c.max_block_replans);
  top.Read("abort_decel_factor", c.abort_decel_factor);
  top.Read("lidar_cutoff_m", c.lidar_cutoff_m);
  top.Read("two_leg_tracking", c.two_leg_tracking);
  top.Read("leg_min_range_m", c.leg_min_range_m);
  top.Read("leg_max_bearing_rad", c.leg_max_bearing_rad);
  top.Read("must_detect_by_m", c.must_detect_by_m);
  top.Read("detection_lost_s", c.detection_lost_s);
  top.Read("scan_timeout_s", c.scan_timeout_s);
  top.Read("lift_timeout_s", c.lift_timeout_s);
  top.Read("timeout_s", c.timeout_s);
  top.Read("control_period_s", c.control_period_s);
  top.RejectUnknown();
  top.Reject(docking::FindConfigViolation(c));  // the rules live with the structs
  return c;
}

}  // namespace shelfdock::io
