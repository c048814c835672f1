// One test per docking config rule (src/docking/docking_config.cpp): the default config passes,
// and breaking exactly that rule is reported with exactly its key.
#include "docking/docking_config.hpp"

#include <functional>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

namespace shelfdock::docking {
namespace {

struct RuleCase {
  std::string name;  ///< test name
  std::string key;   ///< the key the violation must name
  std::function<void(DockingConfig&)> breaks;
};

std::ostream& operator<<(std::ostream& os, const RuleCase& c) { return os << c.name; }

constexpr double kPi = std::numbers::pi;

const RuleCase kCases[] = {
    {"planner_final_straight", "planner.final_straight_m",
     [](auto& c) { c.planner.final_straight_m = 0.0; }},
    {"planner_min_final_straight_negative", "planner.min_final_straight_m",
     [](auto& c) { c.planner.min_final_straight_m = -0.01; }},
    {"planner_min_final_straight_above", "planner.min_final_straight_m",
     [](auto& c) { c.planner.min_final_straight_m = c.planner.final_straight_m + 0.01; }},
    {"planner_curvature", "planner.max_curvature_1pm",
     [](auto& c) { c.planner.max_curvature_1pm = 0.0; }},
    {"planner_sample_step", "planner.sample_step_m",
     [](auto& c) { c.planner.sample_step_m = -0.01; }},
    {"controller_max_speed", "controller.max_speed_mps",
     [](auto& c) { c.controller.max_speed_mps = 0.0; }},
    {"controller_approach_speed", "controller.approach_speed_mps",
     [](auto& c) { c.controller.approach_speed_mps = 0.0; }},
    {"controller_accel", "controller.max_accel_mps2",
     [](auto& c) { c.controller.max_accel_mps2 = 0.0; }},
    {"controller_decel", "controller.max_decel_mps2",
     [](auto& c) { c.controller.max_decel_mps2 = -1.0; }},
    {"controller_yaw_rate", "controller.max_yaw_rate_radps",
     [](auto& c) { c.controller.max_yaw_rate_radps = 0.0; }},
    {"controller_lateral_accel", "controller.max_lateral_accel_mps2",
     [](auto& c) { c.controller.max_lateral_accel_mps2 = 0.0; }},
    {"controller_lateral_settle", "controller.lateral_settle_m",
     [](auto& c) { c.controller.lateral_settle_m = 0.0; }},
    {"controller_approach_lateral_settle", "controller.approach_lateral_settle_m",
     [](auto& c) { c.controller.approach_lateral_settle_m = 0.0; }},
    {"controller_creep_zero", "controller.creep_speed_mps",
     [](auto& c) { c.controller.creep_speed_mps = 0.0; }},
    {"controller_creep_above_max", "controller.creep_speed_mps",
     [](auto& c) { c.controller.creep_speed_mps = c.controller.max_speed_mps; }},
    {"controller_goal_tolerance", "controller.goal_tolerance_m",
     [](auto& c) { c.controller.goal_tolerance_m = 0.0; }},
    {"controller_cross_track", "controller.max_cross_track_m",
     [](auto& c) { c.controller.max_cross_track_m = 0.0; }},
    {"controller_heading_priority", "controller.heading_priority_m",
     [](auto& c) { c.controller.heading_priority_m = -0.001; }},
    {"controller_heading_settle", "controller.heading_settle_m",
     [](auto& c) { c.controller.heading_settle_m = 0.0; }},
    {"tracker_gate_xy", "tracker.gate_xy_m", [](auto& c) { c.tracker.gate_xy_m = 0.0; }},
    {"tracker_gate_yaw", "tracker.gate_yaw_rad", [](auto& c) { c.tracker.gate_yaw_rad = 0.0; }},
    {"tracker_reinit", "tracker.reinit_after_rejects",
     [](auto& c) { c.tracker.reinit_after_rejects = 0; }},
    {"tracker_min_sigma_xy", "tracker.min_sigma_xy_m",
     [](auto& c) { c.tracker.min_sigma_xy_m = 0.0; }},
    {"tracker_min_sigma_yaw", "tracker.min_sigma_yaw_rad",
     [](auto& c) { c.tracker.min_sigma_yaw_rad = 0.0; }},
    {"tracker_drift_xy", "tracker.drift_sigma_xy_per_m",
     [](auto& c) { c.tracker.drift_sigma_xy_per_m = -0.001; }},
    {"tracker_drift_yaw", "tracker.drift_sigma_yaw_per_m",
     [](auto& c) { c.tracker.drift_sigma_yaw_per_m = -0.001; }},
    {"tracker_drift_rate", "tracker.drift_rate_sigma_yaw_per_m",
     [](auto& c) { c.tracker.drift_rate_sigma_yaw_per_m = -0.001; }},
    {"tracker_preset_sigma_xy", "tracker.preset_sigma_xy_m",
     [](auto& c) { c.tracker.preset_sigma_xy_m = 0.0; }},
    {"tracker_preset_sigma_yaw", "tracker.preset_sigma_yaw_rad",
     [](auto& c) { c.tracker.preset_sigma_yaw_rad = 0.0; }},
    {"tracker_preset_gate", "tracker.preset_gate_sigmas",
     [](auto& c) { c.tracker.preset_gate_sigmas = 0.0; }},
    {"safety_length", "safety.robot_length_m", [](auto& c) { c.safety.robot_length_m = 0.0; }},
    {"safety_width", "safety.robot_width_m", [](auto& c) { c.safety.robot_width_m = 0.0; }},
    {"safety_offset", "safety.robot_offset_x_m",
     [](auto& c) { c.safety.robot_offset_x_m = 0.5 * c.safety.robot_length_m; }},
    {"safety_leg_margin", "safety.leg_margin_m", [](auto& c) { c.safety.leg_margin_m = -0.01; }},
    {"safety_obstacle_margin", "safety.obstacle_margin_m",
     [](auto& c) { c.safety.obstacle_margin_m = -0.01; }},
    {"safety_lookahead", "safety.obstacle_lookahead_m",
     [](auto& c) { c.safety.obstacle_lookahead_m = 0.0; }},
    {"safety_wait", "safety.obstacle_wait_s", [](auto& c) { c.safety.obstacle_wait_s = -1.0; }},
    {"safety_neighbour_gap", "safety.obstacle_neighbour_gap_m",
     [](auto& c) { c.safety.obstacle_neighbour_gap_m = -0.1; }},
    {"safety_leg_exclusion", "safety.leg_exclusion_m",
     [](auto& c) { c.safety.leg_exclusion_m = -0.01; }},
    {"verify_frames", "verify.frames", [](auto& c) { c.verify.frames = 0; }},
    {"verify_missing_frames", "verify.max_missing_frames",
     [](auto& c) { c.verify.max_missing_frames = 0; }},
    {"verify_settle", "verify.settle_s", [](auto& c) { c.verify.settle_s = -0.1; }},
    {"verify_tolerance_xy", "verify.tolerance_xy_m",
     [](auto& c) { c.verify.tolerance_xy_m = 0.0; }},
    {"verify_tolerance_yaw", "verify.tolerance_yaw_rad",
     [](auto& c) { c.verify.tolerance_yaw_rad = 0.0; }},
    {"verify_adjust_tries", "verify.max_adjust_tries",
     [](auto& c) { c.verify.max_adjust_tries = -1; }},
    {"verify_lateral_tolerance", "verify.lateral_tolerance_m",
     [](auto& c) { c.verify.lateral_tolerance_m = -0.001; }},
    {"verify_lever_zero", "verify.max_lever_angle_rad",
     [](auto& c) { c.verify.max_lever_angle_rad = 0.0; }},
    {"verify_lever_large", "verify.max_lever_angle_rad",
     [](auto& c) { c.verify.max_lever_angle_rad = 1.5; }},
    {"verify_adjust_speed", "verify.adjust_speed_mps",
     [](auto& c) { c.verify.adjust_speed_mps = 0.0; }},
    {"verify_adjust_accel", "verify.adjust_accel_mps2",
     [](auto& c) { c.verify.adjust_accel_mps2 = 0.0; }},
    {"verify_adjust_yaw_rate", "verify.adjust_yaw_rate_radps",
     [](auto& c) { c.verify.adjust_yaw_rate_radps = 0.0; }},
    {"verify_adjust_yaw_accel", "verify.adjust_yaw_accel_radps2",
     [](auto& c) { c.verify.adjust_yaw_accel_radps2 = 0.0; }},
    {"verify_max_correction", "verify.max_correction_m",
     [](auto& c) { c.verify.max_correction_m = 0.0; }},
    {"guide_camera_on", "camera_guide.camera_on_m",
     [](auto& c) { c.camera_guide.camera_on_m = -0.1; }},
    {"guide_frames", "camera_guide.frames", [](auto& c) { c.camera_guide.frames = 0; }},
    {"guide_min_remaining", "camera_guide.min_remaining_m",
     [](auto& c) { c.camera_guide.min_remaining_m = -0.01; }},
    {"guide_correct_xy", "camera_guide.correct_xy_m",
     [](auto& c) { c.camera_guide.correct_xy_m = 0.0; }},
    {"guide_correct_yaw", "camera_guide.correct_yaw_rad",
     [](auto& c) { c.camera_guide.correct_yaw_rad = 0.0; }},
    {"guide_curvature", "camera_guide.max_curvature_1pm",
     [](auto& c) { c.camera_guide.max_curvature_1pm = 0.0; }},
    {"baseline_parking_zero", "baseline.parking_distance_m",
     [](auto& c) { c.baseline.parking_distance_m = 0.0; }},
    {"baseline_parking_below_straight", "baseline.parking_distance_m",
     [](auto& c) { c.baseline.parking_distance_m = 0.5 * c.planner.min_final_straight_m; }},
    {"baseline_settle", "baseline.settle_s", [](auto& c) { c.baseline.settle_s = -1.0; }},
    {"baseline_scans", "baseline.standing_scans", [](auto& c) { c.baseline.standing_scans = 0; }},
    {"lidar_mount_yaw", "lidar_mount.yaw", [](auto& c) { c.T_base_lidar.yaw = 4.0; }},
    {"dock_yaw_offset", "dock_yaw_offset_rad", [](auto& c) { c.dock_yaw_offset_rad = -4.0; }},
    {"entry_distance", "entry_distance_m", [](auto& c) { c.entry_distance_m = 0.0; }},
    {"min_entry_zero", "min_entry_distance_m", [](auto& c) { c.min_entry_distance_m = 0.0; }},
    {"min_entry_above_entry", "min_entry_distance_m",
     [](auto& c) { c.min_entry_distance_m = c.entry_distance_m + 0.1; }},
    {"entry_tolerance", "entry_tolerance_m", [](auto& c) { c.entry_tolerance_m = -0.01; }},
    {"area_half_width", "area_half_width_m", [](auto& c) { c.area_half_width_m = 0.0; }},
    {"area_max_heading", "area_max_heading_rad", [](auto& c) { c.area_max_heading_rad = 0.0; }},
    {"turn_penalty", "turn_penalty_m", [](auto& c) { c.turn_penalty_m = -0.1; }},
    {"max_move_out", "max_move_out_m", [](auto& c) { c.max_move_out_m = -0.1; }},
    {"max_block_replans", "max_block_replans", [](auto& c) { c.max_block_replans = -1; }},
    {"max_approach_plans", "max_approach_plans", [](auto& c) { c.max_approach_plans = 0; }},
    {"replan_xy", "replan_xy_m", [](auto& c) { c.replan_xy_m = 0.0; }},
    {"replan_yaw", "replan_yaw_rad", [](auto& c) { c.replan_yaw_rad = 0.0; }},
    {"max_replans", "max_replans", [](auto& c) { c.max_replans = -1; }},
    {"lidar_cutoff", "lidar_cutoff_m", [](auto& c) { c.lidar_cutoff_m = -0.1; }},
    {"leg_min_range", "leg_min_range_m", [](auto& c) { c.leg_min_range_m = -0.1; }},
    {"leg_max_bearing_zero", "leg_max_bearing_rad", [](auto& c) { c.leg_max_bearing_rad = 0.0; }},
    {"leg_max_bearing_above_pi", "leg_max_bearing_rad",
     [](auto& c) { c.leg_max_bearing_rad = kPi + 0.1; }},
    {"must_detect_negative", "must_detect_by_m", [](auto& c) { c.must_detect_by_m = -0.1; }},
    {"must_detect_beyond_area", "must_detect_by_m",
     [](auto& c) { c.must_detect_by_m = c.min_entry_distance_m; }},
    {"detection_lost", "detection_lost_s", [](auto& c) { c.detection_lost_s = 0.0; }},
    {"scan_timeout_zero", "scan_timeout_s", [](auto& c) { c.scan_timeout_s = 0.0; }},
    {"scan_timeout_above_lost", "scan_timeout_s",
     [](auto& c) { c.scan_timeout_s = c.detection_lost_s + 0.1; }},
    {"lift_timeout", "lift_timeout_s", [](auto& c) { c.lift_timeout_s = 0.0; }},
    {"timeout", "timeout_s", [](auto& c) { c.timeout_s = -1.0; }},
    {"control_period", "control_period_s", [](auto& c) { c.control_period_s = 0.0; }},
    {"abort_decel", "abort_decel_factor", [](auto& c) { c.abort_decel_factor = 0.9; }},
};

TEST(DockingConfigTest, DefaultsPass) { EXPECT_FALSE(FindConfigViolation(DockingConfig{})); }

class DockingConfigRuleTest : public ::testing::TestWithParam<RuleCase> {};

TEST_P(DockingConfigRuleTest, BreakingTheRuleNamesItsKey) {
  DockingConfig config;
  GetParam().breaks(config);
  const auto v = FindConfigViolation(config);
  ASSERT_TRUE(v.has_value()) << "no violation reported";
  EXPECT_EQ(v->key, GetParam().key) << v->requirement;
  EXPECT_FALSE(v->requirement.empty());
}

INSTANTIATE_TEST_SUITE_P(EveryRule, DockingConfigRuleTest, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return info.param.name; });

// Every numeric field of every struct is under some rule: the struct-level functions see the
// same values as the whole config, under their own keys.
TEST(DockingConfigTest, NestedStructsReportTheirOwnKeys) {
  PlannerConfig planner;
  planner.sample_step_m = 0.0;
  ASSERT_TRUE(FindConfigViolation(planner));
  EXPECT_EQ(FindConfigViolation(planner)->key, "sample_step_m");
  CameraGuideConfig guide;
  guide.correct_yaw_rad = -1.0;
  ASSERT_TRUE(FindConfigViolation(guide));
  EXPECT_EQ(FindConfigViolation(guide)->key, "correct_yaw_rad");
}

}  // namespace
}  // namespace shelfdock::docking
