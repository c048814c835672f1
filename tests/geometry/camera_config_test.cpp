// One test per rule of the camera's intrinsics (src/geometry/camera_intrinsics.cpp) and of the
// upward camera that holds them (src/geometry/upward_camera.cpp): the defaults pass, and
// breaking exactly one rule is reported with exactly its key.
#include "geometry/camera_intrinsics.hpp"

#include <gtest/gtest.h>

#include "../common/config_rules.hpp"
#include "geometry/upward_camera.hpp"

namespace shelfdock::geometry {
namespace {

using shelfdock::testing::ExpectRuleNamesItsKey;
using shelfdock::testing::kRuleName;
using IntrinsicsRule = shelfdock::testing::RuleCase<CameraIntrinsics>;
using CameraRule = shelfdock::testing::RuleCase<UpwardCamera>;

const IntrinsicsRule kIntrinsicsRules[] = {
    {"width_zero", "width_px", [](auto& k) { k.width_px = 0; }},
    {"width_huge", "width_px", [](auto& k) { k.width_px = 32769; }},
    {"height_zero", "height_px", [](auto& k) { k.height_px = 0; }},
    {"height_huge", "height_px", [](auto& k) { k.height_px = 32769; }},
    {"fx", "fx_px", [](auto& k) { k.fx_px = 0.0; }},
    {"fy", "fy_px", [](auto& k) { k.fy_px = -1.0; }},
    {"cx_left", "cx_px", [](auto& k) { k.cx_px = -0.5; }},
    {"cx_right", "cx_px", [](auto& k) { k.cx_px = k.width_px + 0.5; }},
    {"cy_above", "cy_px", [](auto& k) { k.cy_px = -0.5; }},
    {"cy_below", "cy_px", [](auto& k) { k.cy_px = k.height_px + 0.5; }},
};

const CameraRule kCameraRules[] = {
    {"intrinsics", "intrinsics.fx_px", [](auto& c) { c.intrinsics.fx_px = 0.0; }},
    {"code_size", "code.code_size_m", [](auto& c) { c.code_size_m = 0.0; }},
    {"code_height", "code.code_height_m", [](auto& c) { c.code_height_m = -0.3; }},
};

TEST(CameraIntrinsicsTest, DefaultsPass) {
  EXPECT_FALSE(FindConfigViolation(CameraIntrinsics{}));
  EXPECT_FALSE(FindConfigViolation(UpwardCamera{}));
}

TEST(CameraIntrinsicsTest, PrincipalPointMayLieOnTheImageBorder) {
  CameraIntrinsics k;
  k.cx_px = k.width_px;
  k.cy_px = 0.0;
  EXPECT_FALSE(FindConfigViolation(k));
}

class IntrinsicsRuleTest : public ::testing::TestWithParam<IntrinsicsRule> {};
TEST_P(IntrinsicsRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(CameraIntrinsics{}, GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, IntrinsicsRuleTest, ::testing::ValuesIn(kIntrinsicsRules),
                         kRuleName);

class UpwardCameraRuleTest : public ::testing::TestWithParam<CameraRule> {};
TEST_P(UpwardCameraRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(UpwardCamera{}, GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, UpwardCameraRuleTest, ::testing::ValuesIn(kCameraRules),
                         kRuleName);

}  // namespace
}  // namespace shelfdock::geometry
