// Hypotheses compete for leg clusters: the disjoint subset of largest total weight wins.
#include <gtest/gtest.h>

#include <stdexcept>

#include "perception/leg_competition.hpp"

namespace shelfdock::perception {
namespace {

TEST(LegCompetitionTest, PhantomLosesToTheTwoShelvesItBorrowsFrom) {
  // Shelf A = clusters 0-3, shelf B = 4-7, a phantom of A's right and B's left legs (1, 2, 4, 7)
  // that fits its model better than either.
  const std::vector<std::array<int, 4>> legs = {{0, 1, 2, 3}, {4, 5, 6, 7}, {1, 2, 4, 7}};
  const std::vector<double> weights = {3.5, 3.4, 3.9};
  EXPECT_EQ(SelectDisjoint(legs, weights), (std::vector<int>{0, 1}));
}

TEST(LegCompetitionTest, BetterSupportedOfTwoRivalsWinsAndDisjointOnesStay) {
  const std::vector<std::array<int, 4>> legs = {{0, 1, 2, -1}, {0, 1, 2, 3}, {8, 9, 10, 11}};
  const std::vector<double> weights = {2.9, 3.8, 1.0};
  EXPECT_EQ(SelectDisjoint(legs, weights), (std::vector<int>{1, 2}));
}

TEST(LegCompetitionTest, ThreeLegHoleDoesNotConflict) {
  // -1 marks no cluster: two 3-leg shelves never conflict through it.
  const std::vector<std::array<int, 4>> legs = {{0, 1, 2, -1}, {3, 4, 5, -1}};
  EXPECT_EQ(SelectDisjoint(legs, {1.0, 1.0}), (std::vector<int>{0, 1}));
}

TEST(LegCompetitionTest, GreedyFallbackStillReturnsADisjointSet) {
  // A chain of 30 overlapping hypotheses with a node budget of 10: greedy by weight.
  std::vector<std::array<int, 4>> legs;
  std::vector<double> weights;
  for (int i = 0; i < 30; ++i) {
    legs.push_back({i, i + 1, -1, -1});
    weights.push_back(1.0 + 0.01 * (i % 3));
  }
  const std::vector<int> picked = SelectDisjoint(legs, weights, {}, 10);
  ASSERT_FALSE(picked.empty());
  for (std::size_t a = 0; a < picked.size(); ++a) {
    for (std::size_t b = a + 1; b < picked.size(); ++b) {
      EXPECT_GT(std::abs(picked[a] - picked[b]), 1) << "hypotheses share a leg";
    }
  }
}

TEST(LegCompetitionTest, OverlappingFootprintsExcludeEachOtherLikeSharedLegs) {
  // Three leg-disjoint hypotheses; 0 and 2 overlap in space. Without the mark all three stay,
  // with it the lighter of the two goes and the unrelated one stays.
  const std::vector<std::array<int, 4>> legs = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, -1}};
  const std::vector<double> weights = {3.8, 3.5, 2.6};
  std::vector<std::vector<char>> overlap(3, std::vector<char>(3, 0));
  overlap[0][2] = overlap[2][0] = 1;
  EXPECT_EQ(SelectDisjoint(legs, weights), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(SelectDisjoint(legs, weights, overlap), (std::vector<int>{0, 1}));
  // Two lighter hypotheses that each overlap a heavy one outweigh it together.
  overlap[0][1] = overlap[1][0] = 1;
  EXPECT_EQ(SelectDisjoint(legs, {3.8, 2.0, 2.0}, overlap), (std::vector<int>{1, 2}));
}

TEST(LegCompetitionTest, MismatchedSizesAreRejected) {
  const std::vector<std::array<int, 4>> legs = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  EXPECT_THROW(SelectDisjoint(legs, {1.0}), std::invalid_argument);
  EXPECT_THROW(SelectDisjoint(legs, {1.0, 1.0}, {{0, 1}}), std::invalid_argument);
  EXPECT_THROW(SelectDisjoint(legs, {1.0, 1.0}, {{0, 1}, {1}}), std::invalid_argument);
}

TEST(LegCompetitionTest, EmptyInput) { EXPECT_TRUE(SelectDisjoint({}, {}).empty()); }

}  // namespace
}  // namespace shelfdock::perception
