// Paper 3.4 stage tests: shelf pose from 3 or 4 leg centres (Eq. 8-11), yaw near +-pi, a shelf
// behind the sensor, covariance.
#include "perception/shelf_fit.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

std::array<Eigen::Vector2d, 4> Legs(const geometry::ShelfModel& m, const geometry::Pose2& T) {
  std::array<Eigen::Vector2d, 4> legs;
  const auto c = m.LegCentres();
  for (int i = 0; i < 4; ++i) legs[i] = T * c[i];
  return legs;
}

TEST(ShelfFitTest, FourAndThreeLegsAllRoundIncludingNearPi) {
  const auto model = testing::PaperModels()[1];
  const ShelfFitConfig config;
  for (const double yaw : {0.0, 1.0, 3.1400, -3.1400, M_PI - 1e-6, -M_PI}) {
    for (const Eigen::Vector2d& centre : {Eigen::Vector2d(2.0, 0.5), Eigen::Vector2d(-2.5, -0.4)}) {
      // The second centre lies behind the sensor.
      const geometry::Pose2 truth(centre.x(), centre.y(), yaw);
      auto legs = Legs(model, truth);
      for (int count : {4, 3}) {
        const auto fit = FitShelf(legs, count, model, config);
        ASSERT_TRUE(fit.has_value());
        EXPECT_TRUE(fit->converged);
        EXPECT_EQ(fit->legs_used, count);
        EXPECT_LT(geometry::Distance(fit->T_lidar_shelf, truth), 1e-6) << yaw;
        EXPECT_LT(testing::SymmetricYawError(fit->T_lidar_shelf.yaw, yaw, false), 1e-6) << yaw;
        EXPECT_GE(fit->T_lidar_shelf.yaw, -M_PI);
        EXPECT_LT(fit->T_lidar_shelf.yaw, M_PI);
        EXPECT_NEAR(fit->length_m, model.length_m, 1e-9);
        EXPECT_NEAR(fit->width_m, model.width_m, 1e-9);
        EXPECT_LT(fit->rms_m, 1e-6);
      }
    }
  }
}

TEST(ShelfFitTest, OneDisplacedLegAndCovariance) {
  const auto model = testing::PaperModels()[2];
  const ShelfFitConfig config;
  const geometry::Pose2 truth(3.0, 0.2, 0.3);
  auto legs = Legs(model, truth);
  legs[2] += Eigen::Vector2d(0.01, -0.01);  // 14 mm off
  const auto fit = FitShelf(legs, 4, model, config);
  ASSERT_TRUE(fit.has_value());
  // Least squares spreads the error: the centre moves by at most a quarter of it.
  EXPECT_LT(geometry::Distance(fit->T_lidar_shelf, truth), 0.25 * std::sqrt(2.0) * 0.01 + 1e-4);
  EXPECT_GT(fit->rms_m, 0.0);
  // Covariance: symmetric, positive definite, position variance at least the floor / 4 legs.
  const Eigen::Matrix3d& P = fit->covariance;
  EXPECT_LT((P - P.transpose()).norm(), 1e-15);
  EXPECT_GT(P.determinant(), 0.0);
  EXPECT_GE(P(0, 0), config.min_leg_sigma_m * config.min_leg_sigma_m / 4.0 - 1e-12);
}

TEST(ShelfFitTest, RejectsBadCounts) {
  const auto model = testing::PaperModels()[0];
  const auto legs = Legs(model, geometry::Pose2(1.0, 0.0, 0.0));
  EXPECT_FALSE(FitShelf(legs, 2, model, ShelfFitConfig{}).has_value());
  EXPECT_FALSE(FitShelf(legs, 5, model, ShelfFitConfig{}).has_value());
}

}  // namespace
}  // namespace shelfdock::perception
