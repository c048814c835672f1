// One test per rule of a shelf model, its legs and a set of models
// (src/geometry/shelf_model.cpp): the paper's models pass, and breaking exactly one rule is
// reported with exactly its key (as in config/models.yaml).
#include "geometry/shelf_model.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "../common/config_rules.hpp"
#include "../common/paper_models.hpp"

namespace shelfdock::geometry {
namespace {

using shelfdock::testing::ExpectRuleNamesItsKey;
using shelfdock::testing::kRuleName;
using shelfdock::testing::PaperModels;
using shelfdock::testing::PaperShelf2;
using ModelRule = shelfdock::testing::RuleCase<ShelfModel>;
using LegRule = shelfdock::testing::RuleCase<LegModel>;
using ModelsRule = shelfdock::testing::RuleCase<std::vector<ShelfModel>>;

const LegRule kLegRules[] = {
    {"length", "length", [](auto& l) { l.length_m = 0.0; }},
    {"width", "width", [](auto& l) { l.width_m = -0.04; }},
};

const ModelRule kModelRules[] = {
    {"name", "name", [](auto& m) { m.name = ""; }},
    {"length", "length", [](auto& m) { m.length_m = 0.0; }},
    {"width", "width", [](auto& m) { m.width_m = 0.0; }},
    {"length_below_width", "length", [](auto& m) { m.length_m = m.width_m - 0.01; }},
    {"leg", "leg.width", [](auto& m) { m.leg.width_m = 0.0; }},
    {"leg_as_long_as_the_width", "leg.length", [](auto& m) { m.leg.length_m = m.width_m; }},
};

const ModelsRule kModelsRules[] = {
    {"model", "models[1].width", [](auto& models) { models[1].width_m = -1.0; }},
    {"name_twice", "models[2].name", [](auto& models) { models[2].name = models[0].name; }},
};

TEST(ShelfModelTest, ThePaperModelsPass) {
  for (const ShelfModel& m : PaperModels()) EXPECT_FALSE(FindConfigViolation(m)) << m.name;
  EXPECT_FALSE(FindConfigViolation(PaperModels()));
  EXPECT_FALSE(FindConfigViolation(LegModel{}));
}

// A default ShelfModel has no name and no size: a model is always given, never defaulted.
TEST(ShelfModelTest, TheDefaultModelIsNotAModel) {
  ASSERT_TRUE(FindConfigViolation(ShelfModel{}));
  EXPECT_EQ(FindConfigViolation(ShelfModel{})->key, "name");
}

TEST(ShelfModelTest, SquareShelvesPass) {
  ShelfModel m = PaperShelf2();
  m.length_m = m.width_m;
  EXPECT_FALSE(FindConfigViolation(m));
}

class LegModelRuleTest : public ::testing::TestWithParam<LegRule> {};
TEST_P(LegModelRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(PaperShelf2().leg, GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, LegModelRuleTest, ::testing::ValuesIn(kLegRules), kRuleName);

class ShelfModelRuleTest : public ::testing::TestWithParam<ModelRule> {};
TEST_P(ShelfModelRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(PaperShelf2(), GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, ShelfModelRuleTest, ::testing::ValuesIn(kModelRules),
                         kRuleName);

class ShelfModelsRuleTest : public ::testing::TestWithParam<ModelsRule> {};
TEST_P(ShelfModelsRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(PaperModels(), GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, ShelfModelsRuleTest, ::testing::ValuesIn(kModelsRules),
                         kRuleName);

}  // namespace
}  // namespace shelfdock::geometry
