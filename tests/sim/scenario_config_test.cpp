// One test per rule of what a scenario file describes: materials (src/sim/primitive.cpp), paths
// (src/sim/path_motion.cpp), the world's objects (src/sim/world_objects.cpp) and the shelves'
// entries and the scenario itself (src/sim/scenario.cpp). The defaults pass, and breaking
// exactly one rule is reported with exactly its key as in the file's entry.
#include <gtest/gtest.h>

#include "../common/config_rules.hpp"
#include "sim/scenario.hpp"

namespace shelfdock::sim {
namespace {

using shelfdock::testing::ExpectRuleNamesItsKey;
using shelfdock::testing::kRuleName;
template <typename T>
using Rule = shelfdock::testing::RuleCase<T>;

const Rule<Material> kMaterialRules[] = {
    {"reflectivity_negative", "reflectivity", [](auto& m) { m.reflectivity = -0.1; }},
    {"reflectivity_above_one", "reflectivity", [](auto& m) { m.reflectivity = 1.1; }},
};

const Rule<PathMotion> kPathRules[] = {
    {"speed_negative", "speed", [](auto& p) { p.speed_mps = -0.1; }},
    {"speed_ten", "speed", [](auto& p) { p.speed_mps = 10.0; }},
};

const Rule<ShelfInstance> kShelfInstanceRules[] = {
    {"leg_reflectivity", "leg_reflectivity", [](auto& s) { s.leg_material.reflectivity = 1.1; }},
};

const Rule<Wall> kWallRules[] = {
    {"height", "height", [](auto& w) { w.height_m = 0.0; }},
    {"material", "reflectivity", [](auto& w) { w.material.reflectivity = -0.1; }},
};

const Rule<Box> kBoxRules[] = {
    {"length", "length", [](auto& b) { b.length_m = 0.0; }},
    {"width", "width", [](auto& b) { b.width_m = -1.0; }},
    {"height", "height", [](auto& b) { b.height_m = 0.0; }},
    {"material", "reflectivity", [](auto& b) { b.material.reflectivity = 2.0; }},
};

const Rule<Person> kPersonRules[] = {
    {"path", "speed", [](auto& p) { p.path.speed_mps = 10.0; }},
    {"leg_radius", "leg_radius", [](auto& p) { p.leg_radius_m = 0.0; }},
    {"leg_spacing", "leg_spacing", [](auto& p) { p.leg_spacing_m = -0.01; }},
    {"stride", "stride", [](auto& p) { p.stride_m = -0.01; }},
    {"height", "height", [](auto& p) { p.height_m = 0.0; }},
    {"material", "reflectivity", [](auto& p) { p.material.reflectivity = -0.1; }},
};

const Rule<MovingRobot> kMovingRobotRules[] = {
    {"path", "speed", [](auto& r) { r.path.speed_mps = -1.0; }},
    {"length", "length", [](auto& r) { r.length_m = 0.0; }},
    {"width", "width", [](auto& r) { r.width_m = 0.0; }},
    {"height", "height", [](auto& r) { r.height_m = -0.4; }},
    {"material", "reflectivity", [](auto& r) { r.material.reflectivity = 1.5; }},
};

const Rule<ScenarioShelf> kShelfRules[] = {
    {"id", "id", [](auto& s) { s.id = -1; }},
    {"offset_xy_beside_preset", "preset_offset",
     [](auto& s) {
       s.T_map_shelf_preset = s.T_map_shelf;
       s.preset_offset_xy_m = 0.1;
     }},
    {"offset_yaw_beside_preset", "preset_offset",
     [](auto& s) {
       s.T_map_shelf_preset = s.T_map_shelf;
       s.preset_offset_yaw_rad = 0.1;
     }},
    {"offset_xy", "preset_offset.xy_m", [](auto& s) { s.preset_offset_xy_m = -0.1; }},
    {"offset_yaw", "preset_offset.yaw_rad", [](auto& s) { s.preset_offset_yaw_rad = -0.1; }},
};

/// Two shelves (ids 3 and 5), the target one of them.
Scenario TwoShelves() {
  Scenario s;
  s.shelves.resize(2);
  s.shelves[0].id = 3;
  s.shelves[1].id = 5;
  s.target_shelf_id = 5;
  return s;
}

const Rule<Scenario> kScenarioRules[] = {
    {"shelf", "shelves[1].preset_offset.yaw_rad",
     [](auto& s) { s.shelves[1].preset_offset_yaw_rad = -0.1; }},
    {"id_twice", "shelves[1].id", [](auto& s) { s.shelves[1].id = s.shelves[0].id; }},
    {"target", "target_shelf", [](auto& s) { s.target_shelf_id = 4; }},
};

TEST(ScenarioConfigTest, DefaultsPass) {
  EXPECT_FALSE(FindConfigViolation(Material{}));
  EXPECT_FALSE(FindConfigViolation(PathMotion{}));
  EXPECT_FALSE(FindConfigViolation(ShelfInstance{}));
  EXPECT_FALSE(FindConfigViolation(Wall{}));
  EXPECT_FALSE(FindConfigViolation(Box{}));
  EXPECT_FALSE(FindConfigViolation(Person{}));
  EXPECT_FALSE(FindConfigViolation(MovingRobot{}));
  EXPECT_FALSE(FindConfigViolation(ScenarioShelf{}));
  EXPECT_FALSE(FindConfigViolation(Scenario{}));
  EXPECT_FALSE(FindConfigViolation(TwoShelves()));
}

// Standing people and robots, legs side by side, and a stated preset with no offset are fine.
TEST(ScenarioConfigTest, LimitValuesPass) {
  Person person;
  person.path.speed_mps = 0.0;
  person.leg_spacing_m = 0.0;
  person.stride_m = 0.0;
  EXPECT_FALSE(FindConfigViolation(person));
  ScenarioShelf shelf;
  shelf.T_map_shelf_preset = shelf.T_map_shelf;
  EXPECT_FALSE(FindConfigViolation(shelf));
  Scenario none = TwoShelves();
  none.target_shelf_id = -1;  // no target named
  EXPECT_FALSE(FindConfigViolation(none));
}

template <typename T>
class RuleTest : public ::testing::TestWithParam<Rule<T>> {
 protected:
  void Run(const T& valid) { ExpectRuleNamesItsKey(valid, this->GetParam()); }
};

using MaterialRuleTest = RuleTest<Material>;
TEST_P(MaterialRuleTest, BreakingTheRuleNamesItsKey) { Run(Material{}); }
INSTANTIATE_TEST_SUITE_P(EveryRule, MaterialRuleTest, ::testing::ValuesIn(kMaterialRules),
                         kRuleName);

using PathMotionRuleTest = RuleTest<PathMotion>;
TEST_P(PathMotionRuleTest, BreakingTheRuleNamesItsKey) { Run(PathMotion{}); }
INSTANTIATE_TEST_SUITE_P(EveryRule, PathMotionRuleTest, ::testing::ValuesIn(kPathRules), kRuleName);

using ShelfInstanceRuleTest = RuleTest<ShelfInstance>;
TEST_P(ShelfInstanceRuleTest, BreakingTheRuleNamesItsKey) { Run(ShelfInstance{}); }
INSTANTIATE_TEST_SUITE_P(EveryRule, ShelfInstanceRuleTest, ::testing::ValuesIn(kShelfInstanceRules),
                         kRuleName);

using WallRuleTest = RuleTest<Wall>;
TEST_P(WallRuleTest, BreakingTheRuleNamesItsKey) { Run(Wall{}); }
INSTANTIATE_TEST_SUITE_P(EveryRule, WallRuleTest, ::testing::ValuesIn(kWallRules), kRuleName);

using BoxRuleTest = RuleTest<Box>;
TEST_P(BoxRuleTest, BreakingTheRuleNamesItsKey) { Run(Box{}); }
INSTANTIATE_TEST_SUITE_P(EveryRule, BoxRuleTest, ::testing::ValuesIn(kBoxRules), kRuleName);

using PersonRuleTest = RuleTest<Person>;
TEST_P(PersonRuleTest, BreakingTheRuleNamesItsKey) { Run(Person{}); }
INSTANTIATE_TEST_SUITE_P(EveryRule, PersonRuleTest, ::testing::ValuesIn(kPersonRules), kRuleName);

using MovingRobotRuleTest = RuleTest<MovingRobot>;
TEST_P(MovingRobotRuleTest, BreakingTheRuleNamesItsKey) { Run(MovingRobot{}); }
INSTANTIATE_TEST_SUITE_P(EveryRule, MovingRobotRuleTest, ::testing::ValuesIn(kMovingRobotRules),
                         kRuleName);

using ScenarioShelfRuleTest = RuleTest<ScenarioShelf>;
TEST_P(ScenarioShelfRuleTest, BreakingTheRuleNamesItsKey) { Run(ScenarioShelf{}); }
INSTANTIATE_TEST_SUITE_P(EveryRule, ScenarioShelfRuleTest, ::testing::ValuesIn(kShelfRules),
                         kRuleName);

using ScenarioRuleTest = RuleTest<Scenario>;
TEST_P(ScenarioRuleTest, BreakingTheRuleNamesItsKey) { Run(TwoShelves()); }
INSTANTIATE_TEST_SUITE_P(EveryRule, ScenarioRuleTest, ::testing::ValuesIn(kScenarioRules),
                         kRuleName);

}  // namespace
}  // namespace shelfdock::sim
