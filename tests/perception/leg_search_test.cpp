// Paper 3.2 stage tests: pruned rectangle / right-triangle search over cluster centres.
#include "perception/leg_search.hpp"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

std::vector<Eigen::Vector2d> Corners(const geometry::ShelfModel& m, const geometry::Pose2& T) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& c : m.LegCentres()) out.push_back(T * c);
  return out;
}

bool HasSet(const std::vector<LegSet>& sets, std::vector<int> legs) {
  std::sort(legs.begin(), legs.end());
  return std::any_of(sets.begin(), sets.end(), [&](const LegSet& s) {
    std::vector<int> k(s.legs.begin(), s.legs.begin() + s.count);
    std::sort(k.begin(), k.end());
    return k == legs;
  });
}

TEST(LegSearchTest, FindsTheRectangleAndTheRightTriangle) {
  const auto models = testing::PaperModels();
  const LegSearchConfig config;
  const auto legs = Corners(models[1], geometry::Pose2(2.0, 0.3, 0.7));
  const auto four = SearchLegSets(legs, models, config);
  ASSERT_TRUE(HasSet(four, {0, 1, 2, 3}));
  for (const auto& s : four) EXPECT_EQ(s.count, 4);  // no 3-leg subset of a full rectangle
  // One leg hidden: a right triangle, right angle at legs[1].
  const std::vector<Eigen::Vector2d> three{legs[0], legs[1], legs[2]};
  const auto sets = SearchLegSets(three, models, config);
  ASSERT_EQ(sets.size(), 1u);
  EXPECT_EQ(sets[0].count, 3);
  EXPECT_EQ(sets[0].legs[1], 1);
  LegSearchConfig no_three = config;
  no_three.allow_three_legs = false;
  EXPECT_TRUE(SearchLegSets(three, models, no_three).empty());
}

TEST(LegSearchTest, RejectsWrongSizesAndNonRightAngles) {
  const auto models = testing::PaperModels();
  const LegSearchConfig config;
  // Sides 0.6 x 0.4: no model.
  EXPECT_TRUE(SearchLegSets({{0, 0}, {0.6, 0}, {0.6, 0.4}, {0, 0.4}}, models, config).empty());
  // Sides of the 1075x883 model at 60 degrees instead of 90: Pythagoras fails.
  const Eigen::Vector2d v(1, 1);
  const Eigen::Vector2d a = v + 1.075 * Eigen::Vector2d(1, 0);
  const Eigen::Vector2d b = v + 0.883 * Eigen::Vector2d(std::cos(M_PI / 3), std::sin(M_PI / 3));
  EXPECT_TRUE(SearchLegSets({a, v, b}, models, config).empty());
  EXPECT_TRUE(SearchLegSets({}, models, config).empty());
  EXPECT_TRUE(SearchLegSets({v}, models, config).empty());
}

// A shelf among 100 leg-sized candidates: the shelf's set is found, and the pruning keeps the
// number of sets small (the search visits pairs of fitting length only).
TEST(LegSearchTest, HundredCandidatesStillFindTheShelf) {
  const auto models = testing::PaperModels();
  const LegSearchConfig config;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> ux(0.5, 8.0), uy(-5.0, 5.0);
  auto centres = Corners(models[3], geometry::Pose2(3.0, 0.0, 0.2));
  while (centres.size() < 100) centres.emplace_back(ux(rng), uy(rng));
  const auto sets = SearchLegSets(centres, models, config);
  EXPECT_TRUE(HasSet(sets, {0, 1, 2, 3}));
  EXPECT_LT(static_cast<int>(sets.size()), config.max_leg_sets);
}

}  // namespace
}  // namespace shelfdock::perception
