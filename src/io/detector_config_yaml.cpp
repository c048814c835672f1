#include "io/detector_config_yaml.hpp"

#include "io/yaml_fields.hpp"

namespace shelfdock::io {
namespace {

void ReadPreprocess(YamlFields f, perception::PreprocessConfig& c) {
  f.Read("roi_gamma", c.roi_gamma);
  f.Read("cluster_gap_m", c.cluster_gap_m);
  f.Read("cluster_gap_beams", c.cluster_gap_beams);
  f.Read("cluster_max_missing_beams", c.cluster_max_missing_beams);
  f.Read("trailing_min_angle_rad", c.trailing_min_angle_rad);
  f.Read("trailing_min_jump_m", c.trailing_min_jump_m);
  f.Read("leg_extent_margin_m", c.leg_extent_margin_m);
  f.Read("leg_extent_noise_sigmas", c.leg_extent_noise_sigmas);
  f.Read("min_points", c.min_points);
  f.Read("min_point_fraction", c.min_point_fraction);
  f.Read("lone_return_max_beams", c.lone_return_max_beams);
  f.Read("lone_return_min_step_m", c.lone_return_min_step_m);
  f.Read("split_max_extra_m", c.split_max_extra_m);
  f.Read("split_min_step_m", c.split_min_step_m);
  f.Read("split_end_pieces", c.split_end_pieces);
  f.Read("split_inner_pieces", c.split_inner_pieces);
  f.Read("inner_step_sigmas", c.inner_step_sigmas);
  f.Read("inner_offset_sigmas", c.inner_offset_sigmas);
  f.Read("inner_min_offset_m", c.inner_min_offset_m);
  f.Read("inner_surface_points", c.inner_surface_points);
  f.Read("split_noise_steps", c.split_noise_steps);
  f.Read("join_noise_breaks", c.join_noise_breaks);
  f.Read("blend_probe_gap_m", c.blend_probe_gap_m);
  f.Read("blend_any_share", c.blend_any_share);
  f.Read("blend_any_min_bridged", c.blend_any_min_bridged);
  f.Read("surface_tolerance_m", c.surface_tolerance_m);
  f.Read("surface_noise_sigmas", c.surface_noise_sigmas);
  f.Read("surface_max_step_m", c.surface_max_step_m);
  f.RejectUnknown();
}

void ReadLegSearch(YamlFields f, perception::LegSearchConfig& c) {
  f.Read("pair_tolerance_m", c.pair_tolerance_m);
  f.Read("pythagoras_tolerance_m", c.pythagoras_tolerance_m);
  f.Read("fourth_leg_radius_m", c.fourth_leg_radius_m);
  f.Read("allow_three_legs", c.allow_three_legs);
  f.Read("max_leg_sets", c.max_leg_sets);
  f.RejectUnknown();
}

void ReadModelMatch(YamlFields f, perception::ModelMatchConfig& c) {
  f.Read("gamma_L_m", c.gamma_L_m);
  f.Read("gamma_W_m", c.gamma_W_m);
  f.Read("gamma_sum_m", c.gamma_sum_m);
  f.Read("lambda_m", c.lambda_m);
  f.Read("three_leg_err_sum_m", c.three_leg_err_sum_m);
  f.Read("three_leg_err_sum_preset_m", c.three_leg_err_sum_preset_m);
  f.RejectUnknown();
}

void ReadLegFit(YamlFields f, perception::LegFitConfig& c) {
  f.Read("loss_scale_m", c.loss_scale_m);
  f.Read("prior_weight", c.prior_weight);
  f.Read("range_sigma_m", c.range_sigma_m);
  f.Read("silhouette_sigma_beams", c.silhouette_sigma_beams);
  f.Read("pca_min_points", c.pca_min_points);
  f.Read("one_edge_max_points", c.one_edge_max_points);
  f.Read("mixed_edge_share", c.mixed_edge_share);
  f.Read("mixed_min_noise_m", c.mixed_min_noise_m);
  f.Read("pca_min_anisotropy", c.pca_min_anisotropy);
  f.Read("max_iterations", c.max_iterations);
  f.RejectUnknown();
}

void ReadShelfFit(YamlFields f, perception::ShelfFitConfig& c) {
  f.Read("loss_scale_m", c.loss_scale_m);
  f.Read("max_iterations", c.max_iterations);
  f.Read("leg_radial_sigma_m", c.leg_radial_sigma_m);
  f.Read("leg_bearing_sigma_rad", c.leg_bearing_sigma_rad);
  f.Read("min_leg_sigma_m", c.min_leg_sigma_m);
  f.Read("max_rms_m", c.max_rms_m);
  f.Read("background_mix_share", c.background_mix_share);
  f.Read("background_mix_max_m", c.background_mix_max_m);
  f.Read("background_mix_any_cap_m", c.background_mix_any_cap_m);
  f.Read("returns_chi2_margin", c.returns_chi2_margin);
  f.Read("one_edge_bloom_share", c.one_edge_bloom_share);
  f.Read("spot_bloom_share", c.spot_bloom_share);
  f.RejectUnknown();
}

void ReadEvidence(YamlFields f, perception::EvidenceConfig& c) {
  f.Read("present_margin_m", c.present_margin_m);
  f.Read("max_present_object_m", c.max_present_object_m);
  f.Read("present_in_core", c.present_in_core);
  f.Read("through_margin_m", c.through_margin_m);
  f.Read("min_through_beams", c.min_through_beams);
  f.Read("leg_position_tolerance_m", c.leg_position_tolerance_m);
  f.Read("interior_margin_m", c.interior_margin_m);
  f.Read("occluded_credit", c.occluded_credit);
  f.Read("unobserved_credit", c.unobserved_credit);
  f.Read("fit_chi2_three_legs", c.fit_chi2_three_legs);
  f.Read("fit_chi2_four_legs", c.fit_chi2_four_legs);
  f.Read("build_sigma_m", c.build_sigma_m);
  f.Read("range_bias_sigma_m", c.range_bias_sigma_m);
  f.Read("width_bloom_edge_share", c.width_bloom_edge_share);
  f.Read("interior_scale_points", c.interior_scale_points);
  f.Read("foreign_leg_points", c.foreign_leg_points);
  f.Read("foreign_legs_excused", c.foreign_legs_excused);
  f.Read("edge_band_m", c.edge_band_m);
  f.Read("edge_corner_clearance_m", c.edge_corner_clearance_m);
  f.Read("edge_partner_m", c.edge_partner_m);
  f.Read("edge_lone_step_sigmas", c.edge_lone_step_sigmas);
  f.Read("edge_lone_max_beams", c.edge_lone_max_beams);
  f.Read("hider_partner_m", c.hider_partner_m);
  f.Read("object_point_weight", c.object_point_weight);
  f.Read("object_point_spacing_m", c.object_point_spacing_m);
  f.Read("leg_size_margin_m", c.leg_size_margin_m);
  f.Read("leg_width_slack_m", c.leg_width_slack_m);
  f.Read("leg_width_bias_beams", c.leg_width_bias_beams);
  f.Read("leg_width_bias_slack_m", c.leg_width_bias_slack_m);
  f.Read("leg_width_blur_beams", c.leg_width_blur_beams);
  f.Read("leg_width_blend_beams", c.leg_width_blend_beams);
  f.Read("leg_width_skip_blended", c.leg_width_skip_blended);
  f.Read("leg_width_scale_m", c.leg_width_scale_m);
  f.Read("width_bloom_max_rad", c.width_bloom_max_rad);
  f.Read("width_bloom_quantile", c.width_bloom_quantile);
  f.Read("width_bloom_order_share", c.width_bloom_order_share);
  f.Read("width_bloom_min_objects", c.width_bloom_min_objects);
  f.Read("width_bloom_max_extent_m", c.width_bloom_max_extent_m);
  f.Read("width_bloom_min_step_m", c.width_bloom_min_step_m);
  f.Read("width_bloom_own_legs", c.width_bloom_own_legs);
  f.Read("width_bloom_three_legs_beams", c.width_bloom_three_legs_beams);
  f.Read("width_bloom_far_legs", c.width_bloom_far_legs);
  f.Read("blend_max_returns", c.blend_max_returns);
  f.Read("blend_max_step_m", c.blend_max_step_m);
  f.Read("blend_narrow_bias_m", c.blend_narrow_bias_m);
  f.Read("min_confidence", c.min_confidence);
  f.Read("min_confidence_unvouched", c.min_confidence_unvouched);
  f.Read("hidden_leg_competes", c.hidden_leg_competes);
  f.Read("overlap_margin_m", c.overlap_margin_m);
  f.RejectUnknown();
}

void ReadPresetGate(YamlFields f, perception::PresetGateConfig& c) {
  f.Read("max_offset_m", c.max_offset_m);
  f.Read("max_yaw_offset_rad", c.max_yaw_offset_rad);
  f.Read("map_error_m", c.map_error_m);
  f.Read("map_error_yaw_rad", c.map_error_yaw_rad);
  f.RejectUnknown();
}

void ReadCompletion(YamlFields f, perception::LegCompletionConfig& c) {
  f.Read("enabled", c.enabled);
  f.Read("corner_margin_m", c.corner_margin_m);
  f.Read("max_blend_m", c.max_blend_m);
  f.Read("blend_partner_max_m", c.blend_partner_max_m);
  f.Read("blended_max_err_sum_m", c.blended_max_err_sum_m);
  f.Read("blended_min_confidence", c.blended_min_confidence);
  f.Read("min_measured_legs", c.min_measured_legs);
  f.Read("surface_min_offset_m", c.surface_min_offset_m);
  f.Read("surface_offset_sigmas", c.surface_offset_sigmas);
  f.Read("surface_open_end", c.surface_open_end);
  f.Read("candidate_blend_max_m", c.candidate_blend_max_m);
  f.Read("candidate_blend_far_max_m", c.candidate_blend_far_max_m);
  f.Read("blended_candidate_max_returns", c.blended_candidate_max_returns);
  f.Read("blended_candidate_max_step_m", c.blended_candidate_max_step_m);
  f.Read("lone_return_tolerance_m", c.lone_return_tolerance_m);
  f.Read("lone_return_sigmas", c.lone_return_sigmas);
  f.Read("flush_object_max_m", c.flush_object_max_m);
  f.Read("flush_edge_background", c.flush_edge_background);
  f.Read("merged_candidates", c.merged_candidates);
  f.RejectUnknown();
}

}  // namespace

perception::DetectorConfig ReadDetectorConfig(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  perception::DetectorConfig config;
  YamlFields top(root, path, "");
  ReadPreprocess(YamlFields(top.Child("preprocess"), path, "preprocess"), config.preprocess);
  ReadLegSearch(YamlFields(top.Child("leg_search"), path, "leg_search"), config.leg_search);
  ReadModelMatch(YamlFields(top.Child("model_match"), path, "model_match"), config.model_match);
  ReadLegFit(YamlFields(top.Child("leg_fit"), path, "leg_fit"), config.leg_fit);
  ReadShelfFit(YamlFields(top.Child("shelf_fit"), path, "shelf_fit"), config.shelf_fit);
  ReadEvidence(YamlFields(top.Child("evidence"), path, "evidence"), config.evidence);
  ReadPresetGate(YamlFields(top.Child("preset_gate"), path, "preset_gate"), config.preset_gate);
  ReadCompletion(YamlFields(top.Child("completion"), path, "completion"), config.completion);
  top.RejectUnknown();
  top.Reject(perception::FindConfigViolation(config));  // the rules live with the struct
  return config;
}

}  // namespace shelfdock::io
