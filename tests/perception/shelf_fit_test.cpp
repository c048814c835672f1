// Paper 3.4 stage tests: shelf pose from 3 or 4 leg centres (Eq. 8-11), yaw near +-pi, a shelf
// behind the sensor, covariance.
#include "perception/shelf_fit.hpp"

#include <cmath>
#include <random>

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
        EXPECT_LT(testing::SymmetricYawError(fit->T_lidar_shelf.yaw, yaw, model), 1e-6) << yaw;
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

// Sigmas of a leg centre along / across its beam, the same for every leg.
std::array<LegSigma, 4> Sigmas(double along_m, double across_m) {
  std::array<LegSigma, 4> s;
  s.fill(LegSigma{along_m, across_m});
  return s;
}

TEST(RefineShelfPoseTest, ExactLegsGiveTheTruthAndZeroChiSquare) {
  const auto model = testing::PaperModels()[1];
  for (const double yaw : {0.0, 1.0, 3.1400, -M_PI}) {
    const geometry::Pose2 truth(2.0, -0.5, yaw);
    const auto legs = Legs(model, truth);
    for (int count : {4, 3}) {
      const auto fit = FitShelf(legs, count, model, ShelfFitConfig{});
      ASSERT_TRUE(fit.has_value());
      const ShelfRefineResult r = RefineShelfPose(legs, count, model, *fit, Sigmas(0.005, 0.002));
      EXPECT_LT(geometry::Distance(r.T_lidar_shelf, truth), 1e-6) << yaw;
      EXPECT_LT(testing::SymmetricYawError(r.T_lidar_shelf.yaw, yaw, model), 1e-6) << yaw;
      EXPECT_GE(r.T_lidar_shelf.yaw, -M_PI);
      EXPECT_LT(r.T_lidar_shelf.yaw, M_PI);
      EXPECT_LT(r.chi2, 1e-6);
    }
  }
}

// A leg known badly along its beam (few noisy returns) moves the pose little; FitShelf, which
// weighs legs by range alone, follows it further.
TEST(RefineShelfPoseTest, ABadlyKnownLegWeighsLittle) {
  const auto model = testing::PaperModels()[2];
  const geometry::Pose2 truth(2.5, 0.3, 0.4);
  auto legs = Legs(model, truth);
  legs[1] += 0.02 * legs[1].normalized();  // 20 mm too far along its beam
  auto sigma = Sigmas(0.002, 0.002);
  sigma[1].along_m = 0.02;
  const auto fit = FitShelf(legs, 4, model, ShelfFitConfig{});
  ASSERT_TRUE(fit.has_value());
  const ShelfRefineResult r = RefineShelfPose(legs, 4, model, *fit, sigma);
  const double refined_error = geometry::Distance(r.T_lidar_shelf, truth);
  // Its weight is (2/20)^2 = 1/100 of the others': the centre moves well under a millimetre.
  EXPECT_LT(refined_error, 0.001);
  EXPECT_LT(refined_error, geometry::Distance(fit->T_lidar_shelf, truth));
  // The leg stays almost all unexplained: about (20 mm / 20 mm)^2.
  EXPECT_GT(r.chi2, 0.8);
  EXPECT_LT(r.chi2, 1.2);
}

// With leg errors drawn from the stated sigmas the chi-square is chi-square distributed with
// 2 legs - 3 degrees of freedom (mean 5 for four legs, 3 for three), and the wrong one of two
// close models (1075x883 against 1080x856: 27 mm in width) scores worse.
TEST(RefineShelfPoseTest, ChiSquareFollowsItsDistributionAndTellsCloseModelsApart) {
  const auto models = testing::PaperModels();
  const geometry::ShelfModel& right = models[1];  // 1075x883
  const geometry::ShelfModel& wrong = models[3];  // 1080x856
  ASSERT_EQ(right.name, "t1-rect-1075x883");
  ASSERT_EQ(wrong.name, "t1-rect-1080x856");
  const geometry::Pose2 truth(2.2, 0.4, -0.7);
  const std::array<LegSigma, 4> sigma = Sigmas(0.004, 0.002);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  constexpr int kDraws = 2000;
  for (int count : {4, 3}) {
    double sum = 0.0;
    int right_better = 0;
    for (int k = 0; k < kDraws; ++k) {
      auto legs = Legs(right, truth);
      for (int i = 0; i < count; ++i) {
        const Eigen::Vector2d along = legs[i].normalized();
        const Eigen::Vector2d across(-along.y(), along.x());
        legs[i] += sigma[i].along_m * unit(rng) * along + sigma[i].across_m * unit(rng) * across;
      }
      const auto fit_right = FitShelf(legs, count, right, ShelfFitConfig{});
      const auto fit_wrong = FitShelf(legs, count, wrong, ShelfFitConfig{});
      ASSERT_TRUE(fit_right.has_value());
      const double chi2 = RefineShelfPose(legs, count, right, *fit_right, sigma).chi2;
      sum += chi2;
      right_better +=
          !fit_wrong || chi2 < RefineShelfPose(legs, count, wrong, *fit_wrong, sigma).chi2;
    }
    const double dof = 2 * count - 3;
    // The mean of 2000 draws: standard error sqrt(2 dof / 2000) < 0.08; 5 of them allowed.
    EXPECT_NEAR(sum / kDraws, dof, 5.0 * std::sqrt(2.0 * dof / kDraws)) << count << " legs";
    // Four legs measure both widths: always right. Three measure one short edge (its error
    // about 6 mm against 27 mm): measured 1999 of 2000 on this seed; 0.5 % allowed.
    EXPECT_GE(right_better, count == 4 ? kDraws : kDraws - kDraws / 200) << count << " legs";
  }
}

// A scanner reading every range 2 cm long (FitWithRangeBias): a 1250x1250 shelf with the sensor
// under it looks 4 cm larger than its model, so its legs' chi-square against the model is large;
// fitted with the bias it is small, the bias recovered to a millimetre and the pose to one. A
// shelf 3.5 m ahead, its legs' beams 20 degrees apart, mostly moves along them: the pose takes
// most of that up.
TEST(RangeBiasFitTest, LegsAroundTheSensorShowTheBias) {
  const auto model = testing::PaperModels()[2];
  ASSERT_NEAR(model.length_m, 1.25, 1e-9);
  const std::array<int, 4> corners{0, 1, 2, 3};
  const auto sigma = Sigmas(0.003, 0.001);
  const double bias = 0.02;
  auto read_long = [&](std::array<Eigen::Vector2d, 4> legs) {
    for (auto& leg : legs) leg += bias * leg.normalized();
    return legs;
  };
  const geometry::Pose2 under(0.2, -0.1, 0.3);
  const auto legs = read_long(Legs(model, under));
  EXPECT_GT(LegsChiSquare(legs, 4, model, corners, under, sigma), 100.0);
  const RangeBiasFit fit = FitWithRangeBias(legs, 4, model, corners, under, sigma, 0.01);
  EXPECT_NEAR(fit.bias_m, bias, 0.001);
  EXPECT_LT(geometry::Distance(fit.T_lidar_shelf, under), 0.001);
  EXPECT_LT(fit.chi2, 5.0);  // the prior's (b / sigma_b)^2 = 4 and next to nothing else

  const geometry::Pose2 ahead(3.5, 0.0, 0.0);
  const auto far = read_long(Legs(model, ahead));
  const auto shifted = FitShelf(far, 4, model, ShelfFitConfig{});
  ASSERT_TRUE(shifted.has_value());
  const ShelfRefineResult refined = RefineShelfPose(far, 4, model, *shifted, sigma);
  EXPECT_NEAR(refined.T_lidar_shelf.x, ahead.x + bias, 0.005);  // moved along the beams
  EXPECT_LT(refined.chi2, 100.0);  // and so mostly explained (under the sensor: above 100)
  EXPECT_LT(FitWithRangeBias(far, 4, model, corners, ahead, sigma, 0.01).chi2, refined.chi2);
}

}  // namespace
}  // namespace shelfdock::perception
