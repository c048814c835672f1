// One test per rule of the marker detector's settings (src/perception/marker_detector.cpp):
// the defaults pass, and breaking exactly one rule is reported with exactly its key.
#include <gtest/gtest.h>

#include "../common/config_rules.hpp"
#include "perception/marker_detector.hpp"

namespace shelfdock::perception {
namespace {

using shelfdock::testing::ExpectRuleNamesItsKey;
using shelfdock::testing::kRuleName;
using DetectorRule = shelfdock::testing::RuleCase<MarkerDetectorConfig>;

const DetectorRule kRules[] = {
    {"decimate", "quad_decimate", [](auto& c) { c.quad_decimate = 0.9; }},
    {"quad_sigma", "quad_sigma_px", [](auto& c) { c.quad_sigma_px = -0.1; }},
    {"sharpening", "decode_sharpening", [](auto& c) { c.decode_sharpening = -0.1; }},
    {"hamming_negative", "max_hamming", [](auto& c) { c.max_hamming = -1; }},
    {"hamming_three", "max_hamming", [](auto& c) { c.max_hamming = 3; }},
    {"decision_margin", "min_decision_margin", [](auto& c) { c.min_decision_margin = -1.0; }},
    {"height_error", "max_height_error_m", [](auto& c) { c.max_height_error_m = 0.0; }},
};

TEST(MarkerDetectorConfigTest, DefaultsPass) {
  EXPECT_FALSE(FindConfigViolation(MarkerDetectorConfig{}));
}

class MarkerDetectorConfigRuleTest : public ::testing::TestWithParam<DetectorRule> {};
TEST_P(MarkerDetectorConfigRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(MarkerDetectorConfig{}, GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, MarkerDetectorConfigRuleTest, ::testing::ValuesIn(kRules),
                         kRuleName);

}  // namespace
}  // namespace shelfdock::perception
