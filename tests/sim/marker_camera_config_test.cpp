// One test per rule of the camera's rendering config (src/sim/marker_camera.cpp): the defaults
// pass, and breaking exactly one rule is reported with exactly its key as in config/camera.yaml
// (the camera's own rules are tested in tests/geometry/camera_config_test.cpp).
#include <gtest/gtest.h>

#include "../common/config_rules.hpp"
#include "sim/marker_camera.hpp"

namespace shelfdock::sim {
namespace {

using shelfdock::testing::ExpectRuleNamesItsKey;
using shelfdock::testing::kRuleName;
using CameraRule = shelfdock::testing::RuleCase<CameraConfig>;

const CameraRule kRules[] = {
    {"intrinsics", "intrinsics.width_px", [](auto& c) { c.camera.intrinsics.width_px = 0; }},
    {"code", "code.code_size_m", [](auto& c) { c.camera.code_size_m = 0.0; }},
    {"supersample_zero", "render.supersample", [](auto& c) { c.supersample = 0; }},
    {"supersample_many", "render.supersample", [](auto& c) { c.supersample = 17; }},
    {"blur_negative", "render.blur_sigma_px", [](auto& c) { c.blur_sigma_px = -0.1; }},
    {"blur_wide", "render.blur_sigma_px", [](auto& c) { c.blur_sigma_px = 20.1; }},
    {"noise", "render.noise_std", [](auto& c) { c.noise_std = -1.0; }},
    {"exposure", "render.exposure", [](auto& c) { c.exposure = 0.0; }},
    {"white_above_255", "render.white_level", [](auto& c) { c.white_level = 256.0; }},
    {"black_negative", "render.black_level", [](auto& c) { c.black_level = -1.0; }},
    {"background_above_255", "render.background_level",
     [](auto& c) { c.background_level = 256.0; }},
    {"background_negative", "render.background_level", [](auto& c) { c.background_level = -1.0; }},
    {"white_not_above_black", "render.white_level", [](auto& c) { c.white_level = c.black_level; }},
};

TEST(MarkerCameraConfigTest, DefaultsPass) { EXPECT_FALSE(FindConfigViolation(CameraConfig{})); }

// No blur and no noise switch those flaws off.
TEST(MarkerCameraConfigTest, ASharpNoiselessCameraPasses) {
  CameraConfig c;
  c.blur_sigma_px = 0.0;
  c.noise_std = 0.0;
  EXPECT_FALSE(FindConfigViolation(c));
}

class MarkerCameraConfigRuleTest : public ::testing::TestWithParam<CameraRule> {};
TEST_P(MarkerCameraConfigRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(CameraConfig{}, GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, MarkerCameraConfigRuleTest, ::testing::ValuesIn(kRules),
                         kRuleName);

}  // namespace
}  // namespace shelfdock::sim
