#include "docking/shelf_tracker.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {

using geometry::Pose2;

TEST(ShelfTracker, FusedEstimateBeatsSingleDetectionsAndReportsCovariance) {
  const ShelfTrackerConfig config;
  const Pose2 truth(2.0, -0.5, 0.3);
  const double sigma_xy = 0.008, sigma_yaw = 0.01;
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  double sum_err_fused = 0.0;
  const int kTrials = 200;
  for (int trial = 0; trial < kTrials; ++trial) {
    ShelfTracker tracker(config);
    tracker.SetPrior(truth * Pose2(0.2, -0.1, 0.1));
    const Eigen::Matrix3d R =
        Eigen::Vector3d(sigma_xy * sigma_xy, sigma_xy * sigma_xy, sigma_yaw * sigma_yaw)
            .asDiagonal();
    for (int i = 0; i < 16; ++i) {
      tracker.Add(Pose2(truth.x + sigma_xy * n(rng), truth.y + sigma_xy * n(rng),
                        truth.yaw + sigma_yaw * n(rng)),
                  R);
    }
    EXPECT_EQ(tracker.detections(), 16);
    sum_err_fused += geometry::Distance(tracker.estimate(), truth);
    // 16 fused detections: the reported std dev shrinks to ~ sqrt((s^2 + floor^2) / 16).
    const double expected_var =
        (sigma_xy * sigma_xy + config.min_sigma_xy_m * config.min_sigma_xy_m) / 16.0;
    EXPECT_NEAR(tracker.covariance()(0, 0), expected_var, 0.1 * expected_var);
  }
  // Mean 2D error of one detection is sigma * sqrt(pi/2); fusion of 16 must beat it by far.
  const double single = sigma_xy * std::sqrt(std::numbers::pi / 2.0);
  EXPECT_LT(sum_err_fused / kTrials, 0.4 * single);
}

TEST(ShelfTracker, RejectsJumpsAndReinitialisesOnAConsistentNewPose) {
  ShelfTrackerConfig config;
  ShelfTracker tracker(config);
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * 1e-5;
  const Pose2 truth(1.0, 1.0, 0.0);
  EXPECT_EQ(tracker.Add(truth, R), TrackUpdate::kInitialised);
  const Pose2 outlier(1.0 + 2.0 * config.gate_xy_m, 1.0, 0.0);
  EXPECT_EQ(tracker.Add(outlier, R), TrackUpdate::kRejected);
  EXPECT_LT(geometry::Distance(tracker.estimate(), truth), 1e-12);
  // A jump in heading alone is also rejected.
  EXPECT_EQ(tracker.Add(Pose2(1.0, 1.0, 2.0 * config.gate_yaw_rad), R), TrackUpdate::kRejected);
  // The same new pose again and again: the first lock was wrong, restart there.
  TrackUpdate last = TrackUpdate::kFused;
  for (int i = 0; i < config.reinit_after_rejects; ++i) last = tracker.Add(outlier, R);
  EXPECT_EQ(last, TrackUpdate::kReinitialised);
  EXPECT_LT(geometry::Distance(tracker.estimate(), outlier), 1e-12);
}

TEST(ShelfTracker, HeadingAmbiguityByPiIsFoldedTowardTheEstimate) {
  ShelfTracker tracker;
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * 1e-5;
  tracker.Add(Pose2(0.0, 0.0, 3.1), R);
  EXPECT_EQ(tracker.Add(Pose2(0.0, 0.0, 3.1 - std::numbers::pi), R), TrackUpdate::kFused);
  EXPECT_NEAR(geometry::AngleDiff(tracker.estimate().yaw, 3.1), 0.0, 1e-9);
}

TEST(ShelfTracker, DriftInflatesCovarianceWithDistance) {
  ShelfTrackerConfig config;
  ShelfTracker tracker(config);
  tracker.Add(Pose2(), Eigen::Matrix3d::Zero());
  const double before = tracker.covariance()(0, 0);
  tracker.AddOdometryDrift(2.0);
  EXPECT_NEAR(tracker.covariance()(0, 0) - before,
              2.0 * config.drift_sigma_xy_per_m * config.drift_sigma_xy_per_m, 1e-15);
}

}  // namespace
}  // namespace shelfdock::docking
