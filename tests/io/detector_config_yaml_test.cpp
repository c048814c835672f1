#include "io/detector_config_yaml.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "../common/temp_dir.hpp"
#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

std::string WriteTemp(const std::string& name, const std::string& text) {
  const auto path = shelfdock::testing::ProcessTempDir().path() / ("shelfdock_io_" + name);
  std::ofstream(path) << text;
  return path.string();
}

// Expects InputError whose field is `key`.
void ExpectKeyError(const std::string& yaml, const std::string& key) {
  const std::string path = WriteTemp("bad.yaml", yaml);
  try {
    ReadDetectorConfig(path);
    FAIL() << "expected InputError for " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), key);
    EXPECT_EQ(e.file(), path);
  }
}

TEST(DetectorConfigYamlTest, ShippedFileHoldsTheStructDefaults) {
  const perception::DetectorConfig read =
      ReadDetectorConfig(std::string(SHELFDOCK_SOURCE_DIR) + "/config/detector.yaml");
  const perception::DetectorConfig def;
  EXPECT_EQ(read.preprocess.roi_gamma, def.preprocess.roi_gamma);
  EXPECT_EQ(read.preprocess.cluster_gap_m, def.preprocess.cluster_gap_m);
  EXPECT_EQ(read.preprocess.trailing_min_angle_rad, def.preprocess.trailing_min_angle_rad);
  EXPECT_EQ(read.preprocess.min_points, def.preprocess.min_points);
  EXPECT_EQ(read.leg_search.pair_tolerance_m, def.leg_search.pair_tolerance_m);
  EXPECT_EQ(read.leg_search.allow_three_legs, def.leg_search.allow_three_legs);
  EXPECT_EQ(read.model_match.gamma_sum_m, def.model_match.gamma_sum_m);
  EXPECT_EQ(read.model_match.lambda_m, def.model_match.lambda_m);
  EXPECT_EQ(read.leg_fit.loss_scale_m, def.leg_fit.loss_scale_m);
  EXPECT_EQ(read.leg_fit.pca_min_anisotropy, def.leg_fit.pca_min_anisotropy);
  EXPECT_EQ(read.leg_fit.mixed_edge_share, def.leg_fit.mixed_edge_share);
  EXPECT_EQ(read.leg_fit.mixed_min_noise_m, def.leg_fit.mixed_min_noise_m);
  EXPECT_EQ(read.shelf_fit.max_rms_m, def.shelf_fit.max_rms_m);
  EXPECT_EQ(read.evidence.min_confidence, def.evidence.min_confidence);
  EXPECT_EQ(read.evidence.overlap_margin_m, def.evidence.overlap_margin_m);
  EXPECT_EQ(read.evidence.interior_scale_points, def.evidence.interior_scale_points);
  EXPECT_EQ(read.preprocess.split_max_extra_m, def.preprocess.split_max_extra_m);
  EXPECT_EQ(read.preprocess.split_min_step_m, def.preprocess.split_min_step_m);
  EXPECT_EQ(read.preprocess.split_noise_steps, def.preprocess.split_noise_steps);
  EXPECT_EQ(read.preprocess.join_noise_breaks, def.preprocess.join_noise_breaks);
  EXPECT_EQ(read.preprocess.leg_extent_noise_sigmas, def.preprocess.leg_extent_noise_sigmas);
  EXPECT_EQ(read.preprocess.split_end_pieces, def.preprocess.split_end_pieces);
  EXPECT_EQ(read.preprocess.surface_tolerance_m, def.preprocess.surface_tolerance_m);
  EXPECT_EQ(read.preprocess.surface_noise_sigmas, def.preprocess.surface_noise_sigmas);
  EXPECT_EQ(read.preprocess.surface_max_step_m, def.preprocess.surface_max_step_m);
  EXPECT_EQ(read.evidence.fit_chi2_three_legs, def.evidence.fit_chi2_three_legs);
  EXPECT_EQ(read.evidence.fit_chi2_four_legs, def.evidence.fit_chi2_four_legs);
  EXPECT_EQ(read.evidence.build_sigma_m, def.evidence.build_sigma_m);
  EXPECT_EQ(read.evidence.range_bias_sigma_m, def.evidence.range_bias_sigma_m);
}

TEST(DetectorConfigYamlTest, ReadsGivenKeysAndKeepsDefaultsForTheRest) {
  const auto c = ReadDetectorConfig(WriteTemp(
      "ok.yaml", "preprocess: {cluster_gap_m: 0.08}\nleg_search: {allow_three_legs: false}\n"));
  EXPECT_DOUBLE_EQ(c.preprocess.cluster_gap_m, 0.08);
  EXPECT_FALSE(c.leg_search.allow_three_legs);
  EXPECT_EQ(c.model_match.gamma_L_m, perception::ModelMatchConfig{}.gamma_L_m);
  EXPECT_NO_THROW(ReadDetectorConfig(WriteTemp("empty.yaml", "")));
}

// The split and fit-scale keys are read into their own fields (values unlike the defaults).
TEST(DetectorConfigYamlTest, ReadsTheSplitAndFitScaleKeys) {
  const auto c = ReadDetectorConfig(WriteTemp(
      "split.yaml",
      "preprocess: {split_max_extra_m: 0.0, split_min_step_m: 0.045, split_noise_steps: 4.5,\n"
      "             join_noise_breaks: false, leg_extent_noise_sigmas: 1.5,\n"
      "             split_end_pieces: false, surface_tolerance_m: 0.03,\n"
      "             surface_noise_sigmas: 2.5, surface_max_step_m: 0.4}\n"
      "evidence: {fit_chi2_three_legs: 4.5, fit_chi2_four_legs: 20}\n"));
  EXPECT_DOUBLE_EQ(c.preprocess.split_max_extra_m, 0.0);
  EXPECT_DOUBLE_EQ(c.preprocess.split_min_step_m, 0.045);
  EXPECT_DOUBLE_EQ(c.preprocess.split_noise_steps, 4.5);
  EXPECT_FALSE(c.preprocess.join_noise_breaks);
  EXPECT_DOUBLE_EQ(c.preprocess.leg_extent_noise_sigmas, 1.5);
  EXPECT_FALSE(c.preprocess.split_end_pieces);
  EXPECT_DOUBLE_EQ(c.preprocess.surface_tolerance_m, 0.03);
  EXPECT_DOUBLE_EQ(c.preprocess.surface_noise_sigmas, 2.5);
  EXPECT_DOUBLE_EQ(c.preprocess.surface_max_step_m, 0.4);
  EXPECT_DOUBLE_EQ(c.evidence.fit_chi2_three_legs, 4.5);
  EXPECT_DOUBLE_EQ(c.evidence.fit_chi2_four_legs, 20.0);
  // Untouched keys of the same sections keep their defaults.
  EXPECT_EQ(c.preprocess.cluster_gap_m, perception::PreprocessConfig{}.cluster_gap_m);
  EXPECT_EQ(c.evidence.min_confidence, perception::EvidenceConfig{}.min_confidence);
}

TEST(DetectorConfigYamlTest, ErrorsNameTheKey) {
  ExpectKeyError("preprocess: {clustre_gap_m: 0.05}\n", "preprocess.clustre_gap_m");
  ExpectKeyError("preproces: {cluster_gap_m: 0.05}\n", "preproces");
  ExpectKeyError("preprocess: {cluster_gap_m: -0.05}\n", "preprocess.cluster_gap_m");
  ExpectKeyError("preprocess: {roi_gamma: 0.4}\n", "preprocess.roi_gamma");
  ExpectKeyError("leg_fit: {max_iterations: many}\n", "leg_fit.max_iterations");
  ExpectKeyError("evidence: {min_confidence: 1.5}\n", "evidence.min_confidence");
  ExpectKeyError("evidence: {overlap_margin_m: -0.1}\n", "evidence.overlap_margin_m");
  ExpectKeyError("evidence: {occluded_credit: -0.1}\n", "evidence.occluded_credit");
  ExpectKeyError("model_match: {gamma_sum_m: .nan}\n", "model_match.gamma_sum_m");
  // The split and fit-scale keys: impossible values and wrong types.
  ExpectKeyError("preprocess: {split_max_extra_m: -0.1}\n", "preprocess.split_max_extra_m");
  ExpectKeyError("preprocess: {split_min_step_m: 0}\n", "preprocess.split_min_step_m");
  ExpectKeyError("preprocess: {split_noise_steps: -3}\n", "preprocess.split_noise_steps");
  ExpectKeyError("evidence: {fit_chi2_three_legs: 0}\n", "evidence.fit_chi2_three_legs");
  ExpectKeyError("evidence: {fit_chi2_four_legs: -2}\n", "evidence.fit_chi2_four_legs");
  ExpectKeyError("preprocess: {split_min_step_m: three}\n", "preprocess.split_min_step_m");
  ExpectKeyError("evidence: {fit_chi2_four_legs: .nan}\n", "evidence.fit_chi2_four_legs");
  // The fixed err_sum scale and its tolerance factor are gone: an old file names the key.
  ExpectKeyError("evidence: {fit_scale_m: 0.03}\n", "evidence.fit_scale_m");
  ExpectKeyError("preprocess: {split_max_extra: 0.1}\n", "preprocess.split_max_extra");
  EXPECT_THROW(ReadDetectorConfig("/nonexistent/detector.yaml"), InputError);
}

}  // namespace
}  // namespace shelfdock::io
