// Paper 3.2 Eq. 2 stage tests: edge sizes, err_L / err_W / err_sum, lambda pruning.
#include "perception/model_match.hpp"

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

std::array<Eigen::Vector2d, 4> Rect(double a, double b) {
  // Cyclic order, first edge of length a.
  return {Eigen::Vector2d(0, 0), Eigen::Vector2d(a, 0), Eigen::Vector2d(a, b),
          Eigen::Vector2d(0, b)};
}

TEST(ModelMatchTest, MeasureEdgesAveragesOppositeSides) {
  auto legs = Rect(1.0, 0.8);
  legs[2].x() += 0.02;  // one long edge 1.0, the other 1.02 (approximately)
  const EdgeSizes e = MeasureEdges(legs, 4);
  const double far_long = (legs[3] - legs[2]).norm();
  EXPECT_NEAR(e.long_m, 0.5 * (1.0 + far_long), 1e-12);
  EXPECT_TRUE(e.first_edge_long);
  const EdgeSizes t = MeasureEdges(Rect(0.8, 1.0), 3);
  EXPECT_NEAR(t.long_m, 1.0, 1e-12);
  EXPECT_NEAR(t.short_m, 0.8, 1e-12);
  EXPECT_FALSE(t.first_edge_long);
}

TEST(ModelMatchTest, EquationTwoErrorsAndThresholds) {
  const auto models = testing::PaperModels();
  const ModelMatchConfig config;
  EdgeSizes e;
  e.long_m = 1.085;
  e.short_m = 0.873;
  const ModelPair p = ScoreModel(e, models[1], 1);  // 1075 x 883
  EXPECT_NEAR(p.err_L, 0.010, 1e-12);
  EXPECT_NEAR(p.err_W, 0.010, 1e-12);
  EXPECT_NEAR(p.err_sum, 0.020, 1e-12);
  EXPECT_TRUE(PassesThresholds(p, config));
  ModelPair far = p;
  far.err_L = config.gamma_L_m + 1e-3;
  EXPECT_FALSE(PassesThresholds(far, config));
}

// 1075 x 883 and 1080 x 856 differ by 5 mm and 27 mm: exact edges of either pick it first.
TEST(ModelMatchTest, TellsCloseModelsApart) {
  const auto models = testing::PaperModels();
  const ModelMatchConfig config;
  for (const int truth : {1, 3}) {
    const auto pairs = MatchModels(
        MeasureEdges(Rect(models[truth].length_m, models[truth].width_m), 4), models, config);
    ASSERT_FALSE(pairs.empty());
    EXPECT_EQ(pairs.front().model, truth);
    EXPECT_NEAR(pairs.front().err_sum, 0.0, 1e-12);
    // The other close model survives only within lambda of the best (err_sum 0.032 > 0.03).
    for (const auto& q : pairs) EXPECT_LE(q.err_sum - pairs.front().err_sum, config.lambda_m);
  }
  // Nothing fits 0.6 x 0.4.
  EXPECT_TRUE(MatchModels(MeasureEdges(Rect(0.6, 0.4), 4), models, config).empty());
}

}  // namespace
}  // namespace shelfdock::perception
