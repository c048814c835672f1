// One test per detector config rule (src/perception/detector_config.cpp): the default config
// passes, and breaking exactly that rule is reported with exactly its key.
#include "perception/detector_config.hpp"

#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

namespace shelfdock::perception {
namespace {

struct RuleCase {
  std::string name;  ///< test name
  std::string key;   ///< the key the violation must name
  std::function<void(DetectorConfig&)> breaks;
};

std::ostream& operator<<(std::ostream& os, const RuleCase& c) { return os << c.name; }

const RuleCase kCases[] = {
    {"roi_gamma", "preprocess.roi_gamma", [](auto& c) { c.preprocess.roi_gamma = 0.5; }},
    {"cluster_gap", "preprocess.cluster_gap_m", [](auto& c) { c.preprocess.cluster_gap_m = 0.0; }},
    {"cluster_gap_beams", "preprocess.cluster_gap_beams",
     [](auto& c) { c.preprocess.cluster_gap_beams = -1.0; }},
    {"cluster_missing", "preprocess.cluster_max_missing_beams",
     [](auto& c) { c.preprocess.cluster_max_missing_beams = -1; }},
    {"trailing_angle_negative", "preprocess.trailing_min_angle_rad",
     [](auto& c) { c.preprocess.trailing_min_angle_rad = -0.1; }},
    {"trailing_angle_right", "preprocess.trailing_min_angle_rad",
     [](auto& c) { c.preprocess.trailing_min_angle_rad = std::numbers::pi / 2; }},
    {"trailing_jump", "preprocess.trailing_min_jump_m",
     [](auto& c) { c.preprocess.trailing_min_jump_m = -0.01; }},
    {"leg_extent_margin", "preprocess.leg_extent_margin_m",
     [](auto& c) { c.preprocess.leg_extent_margin_m = -0.01; }},
    {"leg_extent_noise", "preprocess.leg_extent_noise_sigmas",
     [](auto& c) { c.preprocess.leg_extent_noise_sigmas = -1.0; }},
    {"surface_tolerance", "preprocess.surface_tolerance_m",
     [](auto& c) { c.preprocess.surface_tolerance_m = -0.01; }},
    {"surface_noise", "preprocess.surface_noise_sigmas",
     [](auto& c) { c.preprocess.surface_noise_sigmas = -1.0; }},
    {"surface_max_step", "preprocess.surface_max_step_m",
     [](auto& c) { c.preprocess.surface_max_step_m = -0.1; }},
    {"min_points", "preprocess.min_points", [](auto& c) { c.preprocess.min_points = 0; }},
    {"min_point_fraction_negative", "preprocess.min_point_fraction",
     [](auto& c) { c.preprocess.min_point_fraction = -0.1; }},
    {"min_point_fraction_above_one", "preprocess.min_point_fraction",
     [](auto& c) { c.preprocess.min_point_fraction = 1.1; }},
    {"lone_return_max_beams", "preprocess.lone_return_max_beams",
     [](auto& c) { c.preprocess.lone_return_max_beams = -1.0; }},
    {"lone_return_min_step", "preprocess.lone_return_min_step_m",
     [](auto& c) { c.preprocess.lone_return_min_step_m = -0.1; }},
    {"split_max_extra_negative", "preprocess.split_max_extra_m",
     [](auto& c) { c.preprocess.split_max_extra_m = -0.01; }},
    {"split_min_step_zero", "preprocess.split_min_step_m",
     [](auto& c) { c.preprocess.split_min_step_m = 0.0; }},
    {"split_min_step_negative", "preprocess.split_min_step_m",
     [](auto& c) { c.preprocess.split_min_step_m = -0.03; }},
    {"split_noise_steps_negative", "preprocess.split_noise_steps",
     [](auto& c) { c.preprocess.split_noise_steps = -1.0; }},
    {"split_max_extra_nan", "preprocess.split_max_extra_m",
     [](auto& c) { c.preprocess.split_max_extra_m = std::numeric_limits<double>::quiet_NaN(); }},
    {"split_min_step_nan", "preprocess.split_min_step_m",
     [](auto& c) { c.preprocess.split_min_step_m = std::numeric_limits<double>::quiet_NaN(); }},
    {"split_noise_steps_nan", "preprocess.split_noise_steps",
     [](auto& c) { c.preprocess.split_noise_steps = std::numeric_limits<double>::quiet_NaN(); }},
    {"pair_tolerance", "leg_search.pair_tolerance_m",
     [](auto& c) { c.leg_search.pair_tolerance_m = 0.0; }},
    {"pythagoras_tolerance", "leg_search.pythagoras_tolerance_m",
     [](auto& c) { c.leg_search.pythagoras_tolerance_m = 0.0; }},
    {"fourth_leg_radius", "leg_search.fourth_leg_radius_m",
     [](auto& c) { c.leg_search.fourth_leg_radius_m = 0.0; }},
    {"max_leg_sets", "leg_search.max_leg_sets", [](auto& c) { c.leg_search.max_leg_sets = 0; }},
    {"gamma_L", "model_match.gamma_L_m", [](auto& c) { c.model_match.gamma_L_m = 0.0; }},
    {"gamma_W", "model_match.gamma_W_m", [](auto& c) { c.model_match.gamma_W_m = 0.0; }},
    {"gamma_sum", "model_match.gamma_sum_m", [](auto& c) { c.model_match.gamma_sum_m = 0.0; }},
    {"lambda", "model_match.lambda_m", [](auto& c) { c.model_match.lambda_m = -0.01; }},
    {"three_leg_err_sum", "model_match.three_leg_err_sum_m",
     [](auto& c) { c.model_match.three_leg_err_sum_m = 0.0; }},
    {"three_leg_err_sum_preset", "model_match.three_leg_err_sum_preset_m",
     [](auto& c) { c.model_match.three_leg_err_sum_preset_m = 0.0; }},
    {"leg_fit_loss", "leg_fit.loss_scale_m", [](auto& c) { c.leg_fit.loss_scale_m = 0.0; }},
    {"leg_fit_prior", "leg_fit.prior_weight", [](auto& c) { c.leg_fit.prior_weight = -0.1; }},
    {"leg_fit_range_sigma", "leg_fit.range_sigma_m",
     [](auto& c) { c.leg_fit.range_sigma_m = 0.0; }},
    {"leg_fit_silhouette_sigma", "leg_fit.silhouette_sigma_beams",
     [](auto& c) { c.leg_fit.silhouette_sigma_beams = 0.0; }},
    {"leg_fit_pca_points", "leg_fit.pca_min_points", [](auto& c) { c.leg_fit.pca_min_points = 1; }},
    {"leg_fit_one_edge_points", "leg_fit.one_edge_max_points",
     [](auto& c) { c.leg_fit.one_edge_max_points = -1; }},
    {"leg_fit_pca_anisotropy", "leg_fit.pca_min_anisotropy",
     [](auto& c) { c.leg_fit.pca_min_anisotropy = 0.9; }},
    {"leg_fit_iterations", "leg_fit.max_iterations", [](auto& c) { c.leg_fit.max_iterations = 0; }},
    {"leg_fit_mixed_share_negative", "leg_fit.mixed_edge_share",
     [](auto& c) { c.leg_fit.mixed_edge_share = -0.1; }},
    {"leg_fit_mixed_share_one", "leg_fit.mixed_edge_share",
     [](auto& c) { c.leg_fit.mixed_edge_share = 1.0; }},
    {"leg_fit_mixed_noise_negative", "leg_fit.mixed_min_noise_m",
     [](auto& c) { c.leg_fit.mixed_min_noise_m = -0.001; }},
    {"shelf_fit_loss", "shelf_fit.loss_scale_m", [](auto& c) { c.shelf_fit.loss_scale_m = 0.0; }},
    {"shelf_fit_iterations", "shelf_fit.max_iterations",
     [](auto& c) { c.shelf_fit.max_iterations = 0; }},
    {"shelf_fit_radial_sigma", "shelf_fit.leg_radial_sigma_m",
     [](auto& c) { c.shelf_fit.leg_radial_sigma_m = 0.0; }},
    {"shelf_fit_bearing_sigma", "shelf_fit.leg_bearing_sigma_rad",
     [](auto& c) { c.shelf_fit.leg_bearing_sigma_rad = 0.0; }},
    {"shelf_fit_min_sigma", "shelf_fit.min_leg_sigma_m",
     [](auto& c) { c.shelf_fit.min_leg_sigma_m = 0.0; }},
    {"shelf_fit_max_rms", "shelf_fit.max_rms_m", [](auto& c) { c.shelf_fit.max_rms_m = 0.0; }},
    {"shelf_fit_returns_chi2_margin", "shelf_fit.returns_chi2_margin",
     [](auto& c) { c.shelf_fit.returns_chi2_margin = -1.0; }},
    {"present_margin", "evidence.present_margin_m",
     [](auto& c) { c.evidence.present_margin_m = 0.0; }},
    {"through_margin", "evidence.through_margin_m",
     [](auto& c) { c.evidence.through_margin_m = 0.0; }},
    {"through_beams", "evidence.min_through_beams",
     [](auto& c) { c.evidence.min_through_beams = 0; }},
    {"leg_position_tolerance", "evidence.leg_position_tolerance_m",
     [](auto& c) { c.evidence.leg_position_tolerance_m = -0.001; }},
    {"interior_margin", "evidence.interior_margin_m",
     [](auto& c) { c.evidence.interior_margin_m = -0.01; }},
    {"occluded_credit_negative", "evidence.occluded_credit",
     [](auto& c) { c.evidence.occluded_credit = -0.1; }},
    {"occluded_credit_above_one", "evidence.occluded_credit",
     [](auto& c) { c.evidence.occluded_credit = 1.1; }},
    {"unobserved_credit_negative", "evidence.unobserved_credit",
     [](auto& c) { c.evidence.unobserved_credit = -0.1; }},
    {"unobserved_credit_above_one", "evidence.unobserved_credit",
     [](auto& c) { c.evidence.unobserved_credit = 1.1; }},
    {"fit_chi2_three_legs_zero", "evidence.fit_chi2_three_legs",
     [](auto& c) { c.evidence.fit_chi2_three_legs = 0.0; }},
    {"fit_chi2_three_legs_nan", "evidence.fit_chi2_three_legs",
     [](auto& c) { c.evidence.fit_chi2_three_legs = std::numeric_limits<double>::quiet_NaN(); }},
    {"fit_chi2_four_legs_negative", "evidence.fit_chi2_four_legs",
     [](auto& c) { c.evidence.fit_chi2_four_legs = -1.0; }},
    {"fit_chi2_four_legs_nan", "evidence.fit_chi2_four_legs",
     [](auto& c) { c.evidence.fit_chi2_four_legs = std::numeric_limits<double>::quiet_NaN(); }},
    {"build_sigma_negative", "evidence.build_sigma_m",
     [](auto& c) { c.evidence.build_sigma_m = -0.001; }},
    {"build_sigma_beyond_a_leg", "evidence.build_sigma_m",
     [](auto& c) { c.evidence.build_sigma_m = 0.06; }},
    {"range_bias_sigma_negative", "evidence.range_bias_sigma_m",
     [](auto& c) { c.evidence.range_bias_sigma_m = -0.01; }},
    {"range_bias_sigma_nan", "evidence.range_bias_sigma_m",
     [](auto& c) { c.evidence.range_bias_sigma_m = std::numeric_limits<double>::quiet_NaN(); }},
    {"interior_scale", "evidence.interior_scale_points",
     [](auto& c) { c.evidence.interior_scale_points = 0.0; }},
    {"foreign_leg_points", "evidence.foreign_leg_points",
     [](auto& c) { c.evidence.foreign_leg_points = -1.0; }},
    {"object_point_weight", "evidence.object_point_weight",
     [](auto& c) { c.evidence.object_point_weight = -0.1; }},
    {"leg_size_margin", "evidence.leg_size_margin_m",
     [](auto& c) { c.evidence.leg_size_margin_m = -0.01; }},
    {"leg_width_slack", "evidence.leg_width_slack_m",
     [](auto& c) { c.evidence.leg_width_slack_m = -0.01; }},
    {"leg_width_bias_beams", "evidence.leg_width_bias_beams",
     [](auto& c) { c.evidence.leg_width_bias_beams = -0.5; }},
    {"leg_width_bias_slack", "evidence.leg_width_bias_slack_m",
     [](auto& c) { c.evidence.leg_width_bias_slack_m = -0.01; }},
    {"leg_width_blur_beams", "evidence.leg_width_blur_beams",
     [](auto& c) { c.evidence.leg_width_blur_beams = -1.0; }},
    {"leg_width_blend_beams", "evidence.leg_width_blend_beams",
     [](auto& c) { c.evidence.leg_width_blend_beams = -0.5; }},
    {"blend_any_share", "preprocess.blend_any_share",
     [](auto& c) { c.preprocess.blend_any_share = 1.5; }},
    {"blend_any_min_bridged", "preprocess.blend_any_min_bridged",
     [](auto& c) { c.preprocess.blend_any_min_bridged = 0; }},
    {"background_mix_any_cap", "shelf_fit.background_mix_any_cap_m",
     [](auto& c) { c.shelf_fit.background_mix_any_cap_m = -0.1; }},
    {"blend_probe_gap", "preprocess.blend_probe_gap_m",
     [](auto& c) { c.preprocess.blend_probe_gap_m = 0.0; }},
    {"leg_width_scale", "evidence.leg_width_scale_m",
     [](auto& c) { c.evidence.leg_width_scale_m = 0.0; }},
    {"width_bloom_max_negative", "evidence.width_bloom_max_rad",
     [](auto& c) { c.evidence.width_bloom_max_rad = -0.001; }},
    {"width_bloom_quantile_above_one", "evidence.width_bloom_quantile",
     [](auto& c) { c.evidence.width_bloom_quantile = 1.1; }},
    {"width_bloom_order_share_negative", "evidence.width_bloom_order_share",
     [](auto& c) { c.evidence.width_bloom_order_share = -0.1; }},
    {"width_bloom_order_share_above_one", "evidence.width_bloom_order_share",
     [](auto& c) { c.evidence.width_bloom_order_share = 1.5; }},
    {"width_bloom_min_objects_zero", "evidence.width_bloom_min_objects",
     [](auto& c) { c.evidence.width_bloom_min_objects = 0; }},
    {"width_bloom_max_extent_zero", "evidence.width_bloom_max_extent_m",
     [](auto& c) { c.evidence.width_bloom_max_extent_m = 0.0; }},
    {"width_bloom_min_step_zero", "evidence.width_bloom_min_step_m",
     [](auto& c) { c.evidence.width_bloom_min_step_m = 0.0; }},
    {"min_confidence_negative", "evidence.min_confidence",
     [](auto& c) { c.evidence.min_confidence = -0.1; }},
    {"min_confidence_one", "evidence.min_confidence",
     [](auto& c) { c.evidence.min_confidence = 1.0; }},
    {"min_confidence_unvouched", "evidence.min_confidence_unvouched",
     [](auto& c) { c.evidence.min_confidence_unvouched = 1.0; }},
    {"overlap_margin", "evidence.overlap_margin_m",
     [](auto& c) { c.evidence.overlap_margin_m = -0.01; }},
    {"preset_gate_offset", "preset_gate.max_offset_m",
     [](auto& c) { c.preset_gate.max_offset_m = -0.1; }},
    {"preset_gate_yaw", "preset_gate.max_yaw_offset_rad",
     [](auto& c) { c.preset_gate.max_yaw_offset_rad = -0.1; }},
    {"completion_margin", "completion.corner_margin_m",
     [](auto& c) { c.completion.corner_margin_m = -0.01; }},
    {"max_blend", "completion.max_blend_m", [](auto& c) { c.completion.max_blend_m = -0.1; }},
    {"blend_partner", "completion.blend_partner_max_m",
     [](auto& c) { c.completion.blend_partner_max_m = -0.1; }},
    {"blended_err_sum", "completion.blended_max_err_sum_m",
     [](auto& c) { c.completion.blended_max_err_sum_m = 0.0; }},
    {"blended_confidence", "completion.blended_min_confidence",
     [](auto& c) { c.completion.blended_min_confidence = 1.0; }},
    {"measured_legs", "completion.min_measured_legs",
     [](auto& c) { c.completion.min_measured_legs = 4; }},
    {"surface_offset", "completion.surface_min_offset_m",
     [](auto& c) { c.completion.surface_min_offset_m = 0.0; }},
    {"surface_sigmas", "completion.surface_offset_sigmas",
     [](auto& c) { c.completion.surface_offset_sigmas = -1.0; }},
    {"candidate_blend", "completion.candidate_blend_max_m",
     [](auto& c) { c.completion.candidate_blend_max_m = -0.01; }},
    {"candidate_blend_far", "completion.candidate_blend_far_max_m",
     [](auto& c) { c.completion.candidate_blend_far_max_m = -0.01; }},
    {"blended_candidate_returns", "completion.blended_candidate_max_returns",
     [](auto& c) { c.completion.blended_candidate_max_returns = -1; }},
    {"blended_candidate_step", "completion.blended_candidate_max_step_m",
     [](auto& c) { c.completion.blended_candidate_max_step_m = 0.0; }},
    {"lone_tolerance", "completion.lone_return_tolerance_m",
     [](auto& c) { c.completion.lone_return_tolerance_m = -0.01; }},
    {"lone_sigmas", "completion.lone_return_sigmas",
     [](auto& c) { c.completion.lone_return_sigmas = -1.0; }},
    {"edge_band", "evidence.edge_band_m", [](auto& c) { c.evidence.edge_band_m = -0.01; }},
    {"edge_clearance", "evidence.edge_corner_clearance_m",
     [](auto& c) { c.evidence.edge_corner_clearance_m = -0.1; }},
    {"edge_partner", "evidence.edge_partner_m", [](auto& c) { c.evidence.edge_partner_m = -0.1; }},
    {"edge_lone_step", "evidence.edge_lone_step_sigmas",
     [](auto& c) { c.evidence.edge_lone_step_sigmas = -1.0; }},
    {"edge_lone_beams", "evidence.edge_lone_max_beams",
     [](auto& c) { c.evidence.edge_lone_max_beams = -1.0; }},
    {"hider_partner", "evidence.hider_partner_m",
     [](auto& c) { c.evidence.hider_partner_m = -0.1; }},
    {"map_error", "preset_gate.map_error_m", [](auto& c) { c.preset_gate.map_error_m = 0.0; }},
    {"map_error_yaw", "preset_gate.map_error_yaw_rad",
     [](auto& c) { c.preset_gate.map_error_yaw_rad = 0.0; }},
    {"map_error_beyond_gate", "preset_gate.map_error_m",
     [](auto& c) { c.preset_gate.map_error_m = 0.6; }},
    {"map_error_yaw_beyond_gate", "preset_gate.map_error_yaw_rad",
     [](auto& c) { c.preset_gate.map_error_yaw_rad = 0.4; }},
};

TEST(DetectorConfigTest, DefaultsPass) { EXPECT_FALSE(FindConfigViolation(DetectorConfig{})); }

// The new keys' limits are allowed values: 0 turns the split off, 0 noise steps leave only
// split_min_step_m; a tiny positive step or fit chi-square scale is valid too.
TEST(DetectorConfigTest, SplitAndFitScaleLimitsPass) {
  DetectorConfig c;
  c.preprocess.split_max_extra_m = 0.0;
  c.preprocess.split_noise_steps = 0.0;
  c.preprocess.split_min_step_m = 1e-6;
  c.evidence.fit_chi2_three_legs = 1e-6;
  c.evidence.fit_chi2_four_legs = 1e-6;
  const auto v = FindConfigViolation(c);
  EXPECT_FALSE(v.has_value()) << v->key << " " << v->requirement;
}

class DetectorConfigRuleTest : public ::testing::TestWithParam<RuleCase> {};

TEST_P(DetectorConfigRuleTest, BreakingTheRuleNamesItsKey) {
  DetectorConfig config;
  GetParam().breaks(config);
  const auto v = FindConfigViolation(config);
  ASSERT_TRUE(v.has_value()) << "no violation reported";
  EXPECT_EQ(v->key, GetParam().key) << v->requirement;
  EXPECT_FALSE(v->requirement.empty());
}

INSTANTIATE_TEST_SUITE_P(EveryRule, DetectorConfigRuleTest, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace shelfdock::perception
