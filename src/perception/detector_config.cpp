#include "perception/detector_config.hpp"

#include <numbers>

namespace shelfdock::perception {

std::optional<ConfigViolation> FindConfigViolation(const DetectorConfig& c) {
  geometry::ConfigChecker k;
  const auto& p = c.preprocess;
  k.Check(p.roi_gamma > 0.5, "preprocess.roi_gamma", "> 0.5 (the ROI must reach the legs)");
  k.Check(p.cluster_gap_m > 0.0, "preprocess.cluster_gap_m", "> 0");
  k.Check(p.cluster_gap_beams >= 0.0, "preprocess.cluster_gap_beams", ">= 0");
  k.Check(p.cluster_max_missing_beams >= 0, "preprocess.cluster_max_missing_beams", ">= 0");
  k.Check(p.trailing_min_angle_rad >= 0.0 && p.trailing_min_angle_rad < std::numbers::pi / 2,
          "preprocess.trailing_min_angle_rad", "in [0, pi/2)");
  k.Check(p.trailing_min_jump_m >= 0.0, "preprocess.trailing_min_jump_m", ">= 0");
  k.Check(p.leg_extent_margin_m >= 0.0, "preprocess.leg_extent_margin_m", ">= 0");
  k.Check(p.leg_extent_noise_sigmas >= 0.0, "preprocess.leg_extent_noise_sigmas", ">= 0");
  k.Check(p.surface_tolerance_m >= 0.0, "preprocess.surface_tolerance_m", ">= 0");
  k.Check(p.surface_noise_sigmas >= 0.0, "preprocess.surface_noise_sigmas", ">= 0");
  k.Check(p.surface_max_step_m >= 0.0, "preprocess.surface_max_step_m", ">= 0");
  k.Check(p.min_points >= 1, "preprocess.min_points", ">= 1");
  k.Check(p.split_max_extra_m >= 0.0, "preprocess.split_max_extra_m", ">= 0 (0: never split)");
  k.Check(p.split_min_step_m > 0.0, "preprocess.split_min_step_m", "> 0");
  k.Check(p.split_noise_steps >= 0.0, "preprocess.split_noise_steps", ">= 0");
  k.Check(p.inner_step_sigmas >= 0.0, "preprocess.inner_step_sigmas", ">= 0");
  k.Check(p.inner_offset_sigmas >= 0.0, "preprocess.inner_offset_sigmas", ">= 0");
  k.Check(p.inner_min_offset_m >= 0.0, "preprocess.inner_min_offset_m", ">= 0");
  k.Check(p.inner_surface_points >= 2, "preprocess.inner_surface_points",
          ">= 2 (a line on each side)");
  k.Check(p.min_point_fraction >= 0.0 && p.min_point_fraction <= 1.0,
          "preprocess.min_point_fraction", "in [0, 1]");
  k.Check(p.lone_return_max_beams >= 0.0, "preprocess.lone_return_max_beams", ">= 0 (0: off)");
  k.Check(p.lone_return_min_step_m >= 0.0, "preprocess.lone_return_min_step_m", ">= 0");
  k.Check(p.blend_probe_gap_m > 0.0, "preprocess.blend_probe_gap_m", "> 0");
  k.Check(p.blend_any_share >= 0.0 && p.blend_any_share <= 1.0, "preprocess.blend_any_share",
          "in [0, 1] (0: never)");
  k.Check(p.blend_any_min_bridged >= 1, "preprocess.blend_any_min_bridged", ">= 1");

  const auto& s = c.leg_search;
  k.Check(s.pair_tolerance_m > 0.0, "leg_search.pair_tolerance_m", "> 0");
  k.Check(s.pythagoras_tolerance_m > 0.0, "leg_search.pythagoras_tolerance_m", "> 0");
  k.Check(s.fourth_leg_radius_m > 0.0, "leg_search.fourth_leg_radius_m", "> 0");
  k.Check(s.max_leg_sets >= 1, "leg_search.max_leg_sets", ">= 1");

  const auto& m = c.model_match;
  k.Check(m.gamma_L_m > 0.0, "model_match.gamma_L_m", "> 0");
  k.Check(m.gamma_W_m > 0.0, "model_match.gamma_W_m", "> 0");
  k.Check(m.gamma_sum_m > 0.0, "model_match.gamma_sum_m", "> 0");
  k.Check(m.lambda_m >= 0.0, "model_match.lambda_m", ">= 0");
  k.Check(m.three_leg_err_sum_m > 0.0, "model_match.three_leg_err_sum_m", "> 0");
  k.Check(m.three_leg_err_sum_preset_m > 0.0, "model_match.three_leg_err_sum_preset_m", "> 0");

  const auto& l = c.leg_fit;
  k.Check(l.loss_scale_m > 0.0, "leg_fit.loss_scale_m", "> 0");
  k.Check(l.prior_weight >= 0.0, "leg_fit.prior_weight", ">= 0");
  k.Check(l.range_sigma_m > 0.0, "leg_fit.range_sigma_m", "> 0");
  k.Check(l.silhouette_sigma_beams > 0.0, "leg_fit.silhouette_sigma_beams", "> 0");
  k.Check(l.pca_min_points >= 2, "leg_fit.pca_min_points", ">= 2");
  k.Check(l.one_edge_max_points >= 0, "leg_fit.one_edge_max_points", ">= 0");
  k.Check(l.pca_min_anisotropy >= 1.0, "leg_fit.pca_min_anisotropy", ">= 1");
  k.Check(l.max_iterations >= 1, "leg_fit.max_iterations", ">= 1");
  k.Check(l.mixed_edge_share >= 0.0 && l.mixed_edge_share < 1.0, "leg_fit.mixed_edge_share",
          "in [0, 1)");
  k.Check(l.mixed_min_noise_m >= 0.0, "leg_fit.mixed_min_noise_m", ">= 0");

  const auto& f = c.shelf_fit;
  k.Check(f.loss_scale_m > 0.0, "shelf_fit.loss_scale_m", "> 0");
  k.Check(f.max_iterations >= 1, "shelf_fit.max_iterations", ">= 1");
  k.Check(f.leg_radial_sigma_m > 0.0, "shelf_fit.leg_radial_sigma_m", "> 0");
  k.Check(f.leg_bearing_sigma_rad > 0.0, "shelf_fit.leg_bearing_sigma_rad", "> 0");
  k.Check(f.min_leg_sigma_m > 0.0, "shelf_fit.min_leg_sigma_m", "> 0");
  k.Check(f.max_rms_m > 0.0, "shelf_fit.max_rms_m", "> 0");
  k.Check(f.background_mix_share >= 0.0, "shelf_fit.background_mix_share", ">= 0");
  k.Check(f.background_mix_max_m >= 0.0, "shelf_fit.background_mix_max_m", ">= 0 (0: off)");
  k.Check(f.background_mix_any_cap_m >= 0.0, "shelf_fit.background_mix_any_cap_m",
          ">= 0 (0: never)");
  k.Check(f.returns_chi2_margin >= 0.0, "shelf_fit.returns_chi2_margin", ">= 0 (0: never)");
  k.Check(f.one_edge_bloom_share >= 0.0, "shelf_fit.one_edge_bloom_share", ">= 0 (0: off)");
  k.Check(f.spot_bloom_share >= 0.0, "shelf_fit.spot_bloom_share", ">= 0 (0: off)");

  const auto& e = c.evidence;
  k.Check(e.present_margin_m > 0.0, "evidence.present_margin_m", "> 0");
  k.Check(e.max_present_object_m >= 0.0, "evidence.max_present_object_m", ">= 0");
  k.Check(e.through_margin_m > 0.0, "evidence.through_margin_m", "> 0");
  k.Check(e.min_through_beams >= 1, "evidence.min_through_beams", ">= 1");
  k.Check(e.leg_position_tolerance_m >= 0.0, "evidence.leg_position_tolerance_m", ">= 0");
  k.Check(e.interior_margin_m >= 0.0, "evidence.interior_margin_m", ">= 0");
  k.Check(e.occluded_credit >= 0.0 && e.occluded_credit <= 1.0, "evidence.occluded_credit",
          "in [0, 1]");
  k.Check(e.unobserved_credit >= 0.0 && e.unobserved_credit <= 1.0, "evidence.unobserved_credit",
          "in [0, 1]");
  k.Check(e.fit_chi2_three_legs > 0.0, "evidence.fit_chi2_three_legs", "> 0");
  k.Check(e.fit_chi2_four_legs > 0.0, "evidence.fit_chi2_four_legs", "> 0");
  k.Check(e.build_sigma_m >= 0.0 && e.build_sigma_m <= 0.05, "evidence.build_sigma_m",
          "in [0, 0.05] (a leg farther off its model's place is no longer that model's)");
  k.Check(e.range_bias_sigma_m >= 0.0 && e.range_bias_sigma_m <= 0.1, "evidence.range_bias_sigma_m",
          "in [0, 0.1] (metres; 0: off)");
  k.Check(e.width_bloom_edge_share >= 0.0 && e.width_bloom_edge_share <= 1.0,
          "evidence.width_bloom_edge_share", "in [0, 1] (0: off)");
  k.Check(e.interior_scale_points > 0.0, "evidence.interior_scale_points", "> 0");
  k.Check(e.foreign_leg_points >= 0.0, "evidence.foreign_leg_points", ">= 0");
  k.Check(e.foreign_legs_excused >= 0, "evidence.foreign_legs_excused", ">= 0 (0: off)");
  k.Check(e.edge_band_m >= 0.0, "evidence.edge_band_m", ">= 0 (0: off)");
  k.Check(e.edge_corner_clearance_m >= 0.0, "evidence.edge_corner_clearance_m", ">= 0");
  k.Check(e.edge_partner_m >= 0.0, "evidence.edge_partner_m", ">= 0");
  k.Check(e.edge_lone_step_sigmas >= 0.0, "evidence.edge_lone_step_sigmas", ">= 0 (0: any step)");
  k.Check(e.edge_lone_max_beams >= 0.0, "evidence.edge_lone_max_beams", ">= 0 (0: any range)");
  k.Check(e.hider_partner_m >= 0.0, "evidence.hider_partner_m", ">= 0 (0: off)");
  k.Check(e.object_point_weight >= 0.0, "evidence.object_point_weight", ">= 0");
  k.Check(e.object_point_spacing_m >= 0.0, "evidence.object_point_spacing_m", ">= 0");
  k.Check(e.leg_size_margin_m >= 0.0, "evidence.leg_size_margin_m", ">= 0");
  k.Check(e.leg_width_slack_m >= 0.0, "evidence.leg_width_slack_m", ">= 0");
  k.Check(e.leg_width_bias_beams >= 0.0, "evidence.leg_width_bias_beams", ">= 0");
  k.Check(e.leg_width_bias_slack_m >= 0.0, "evidence.leg_width_bias_slack_m", ">= 0");
  k.Check(e.leg_width_blur_beams >= 0.0, "evidence.leg_width_blur_beams", ">= 0 (0: off)");
  k.Check(e.leg_width_blend_beams >= 0.0, "evidence.leg_width_blend_beams", ">= 0 (0: off)");
  k.Check(e.leg_width_scale_m > 0.0, "evidence.leg_width_scale_m", "> 0");
  k.Check(e.width_bloom_max_rad >= 0.0, "evidence.width_bloom_max_rad", ">= 0 (0: off)");
  k.Check(e.width_bloom_quantile >= 0.0 && e.width_bloom_quantile <= 1.0,
          "evidence.width_bloom_quantile", "in [0, 1]");
  k.Check(e.width_bloom_order_share >= 0.0 && e.width_bloom_order_share <= 1.0,
          "evidence.width_bloom_order_share", "in [0, 1]");
  k.Check(e.width_bloom_min_objects >= 1, "evidence.width_bloom_min_objects", ">= 1");
  k.Check(e.width_bloom_three_legs_beams >= 0.0, "evidence.width_bloom_three_legs_beams", ">= 0");
  k.Check(e.width_bloom_max_extent_m > 0.0, "evidence.width_bloom_max_extent_m", "> 0");
  k.Check(e.width_bloom_min_step_m > 0.0, "evidence.width_bloom_min_step_m", "> 0");
  k.Check(e.blend_max_returns >= 0, "evidence.blend_max_returns", ">= 0 (0: off)");
  k.Check(e.blend_max_step_m > 0.0, "evidence.blend_max_step_m", "> 0");
  k.Check(e.blend_narrow_bias_m >= 0.0, "evidence.blend_narrow_bias_m", ">= 0");
  k.Check(e.min_confidence >= 0.0 && e.min_confidence < 1.0, "evidence.min_confidence",
          "in [0, 1)");
  k.Check(e.min_confidence_unvouched >= 0.0 && e.min_confidence_unvouched < 1.0,
          "evidence.min_confidence_unvouched", "in [0, 1)");
  k.Check(e.overlap_margin_m >= 0.0, "evidence.overlap_margin_m", ">= 0");

  const auto& g = c.preset_gate;
  k.Check(g.max_offset_m >= 0.0, "preset_gate.max_offset_m", ">= 0 (0: off)");
  k.Check(g.max_yaw_offset_rad >= 0.0, "preset_gate.max_yaw_offset_rad", ">= 0 (0: off)");
  k.Check(g.map_error_m > 0.0, "preset_gate.map_error_m", "> 0");
  k.Check(g.map_error_yaw_rad > 0.0, "preset_gate.map_error_yaw_rad", "> 0");
  k.Check(g.max_offset_m <= 0.0 || g.map_error_m <= g.max_offset_m, "preset_gate.map_error_m",
          "<= preset_gate.max_offset_m (the map's error lies inside the gate)");
  k.Check(g.max_yaw_offset_rad <= 0.0 || g.map_error_yaw_rad <= g.max_yaw_offset_rad,
          "preset_gate.map_error_yaw_rad", "<= preset_gate.max_yaw_offset_rad");
  k.Check(c.completion.corner_margin_m >= 0.0, "completion.corner_margin_m", ">= 0");
  k.Check(c.completion.max_blend_m >= 0.0, "completion.max_blend_m", ">= 0 (0: off)");
  k.Check(c.completion.blend_partner_max_m >= 0.0, "completion.blend_partner_max_m",
          ">= 0 (0: off)");
  k.Check(c.completion.blended_max_err_sum_m > 0.0, "completion.blended_max_err_sum_m", "> 0");
  k.Check(c.completion.blended_min_confidence >= 0.0 && c.completion.blended_min_confidence < 1.0,
          "completion.blended_min_confidence", "in [0, 1)");
  k.Check(c.completion.min_measured_legs >= 0 && c.completion.min_measured_legs <= 3,
          "completion.min_measured_legs", "in [0, 3]");
  k.Check(c.completion.surface_min_offset_m > 0.0, "completion.surface_min_offset_m", "> 0");
  k.Check(c.completion.surface_offset_sigmas >= 0.0, "completion.surface_offset_sigmas",
          ">= 0 (0: off)");
  k.Check(c.completion.candidate_blend_max_m >= 0.0, "completion.candidate_blend_max_m",
          ">= 0 (0: off)");
  k.Check(c.completion.candidate_blend_far_max_m >= 0.0, "completion.candidate_blend_far_max_m",
          ">= 0 (at most candidate_blend_max_m: off)");
  k.Check(c.completion.blended_candidate_max_returns >= 0,
          "completion.blended_candidate_max_returns", ">= 0 (0: off)");
  k.Check(c.completion.blended_candidate_max_step_m > 0.0,
          "completion.blended_candidate_max_step_m", "> 0");
  k.Check(c.completion.lone_return_tolerance_m >= 0.0, "completion.lone_return_tolerance_m",
          ">= 0");
  k.Check(c.completion.lone_return_sigmas >= 0.0, "completion.lone_return_sigmas",
          ">= 0 (both 0: off)");
  k.Check(c.completion.flush_object_max_m >= 0.0, "completion.flush_object_max_m", ">= 0 (0: off)");
  return k.Result();
}

}  // namespace shelfdock::perception
