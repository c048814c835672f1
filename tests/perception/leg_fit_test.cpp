// Paper 3.3 stage tests: PCA direction and leg centres against analytic ray-cast points.
#include "perception/leg_fit.hpp"

#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kAlpha = 0.005817764173314432;  // WLR-716: 1/3 degree

geometry::LegModel Round26() { return {geometry::LegShape::kCircle, 0.026, 0.026}; }
geometry::LegModel Square40() { return {geometry::LegShape::kRectangle, 0.04, 0.04}; }

TEST(LegFitTest, PcaFindsTheMainDirectionOfAFace) {
  std::vector<ScanPoint> pts;
  const double yaw = 0.4;
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector2d p =
        Eigen::Vector2d(2.0, 0.5) + 0.004 * i * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
    pts.push_back({p, p.norm(), std::atan2(p.y(), p.x()), i});
  }
  const PcaDirection pca = PrincipalDirection(pts);
  EXPECT_NEAR(std::abs(std::sin(pca.yaw - yaw)), 0.0, 1e-9);
  EXPECT_GT(pca.anisotropy, 1e6);
}

// Exact points: the fit recovers the centre, the bare centroid is biased toward the sensor by
// about pi/4 r (circle) or half the depth (box).
TEST(LegFitTest, ExactPointsGiveTheCentreAndRemoveTheCentroidBias) {
  // Exact ranges: the silhouette's centre bearing (only known to within a beam step) must not
  // outweigh them.
  LegFitConfig config;
  config.range_sigma_m = 1e-6;
  const Eigen::Vector2d c(1.2, 0.4);
  const auto circle = testing::CastCircle(c, 0.013, kAlpha);
  ASSERT_GE(circle.size(), 3u);
  const LegFitResult fc = FitLeg(circle, Round26(), 0.0, config);
  EXPECT_TRUE(fc.converged);
  EXPECT_LT((fc.centre - c).norm(), 0.5e-3);
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const auto& q : circle) centroid += q.p / static_cast<double>(circle.size());
  EXPECT_GT((centroid - c).norm(), 0.006);

  for (const double yaw : {0.0, 0.3, -0.7, 3.0}) {
    const geometry::Pose2 T_lidar_leg(1.5, -0.6, yaw);
    const auto box = testing::CastBox(T_lidar_leg, 0.04, 0.04, kAlpha);
    ASSERT_GE(box.size(), 3u);
    const LegFitResult fb = FitLeg(box, Square40(), yaw, config);
    EXPECT_TRUE(fb.converged);
    EXPECT_LT((fb.centre - T_lidar_leg.translation()).norm(), 1e-3) << "yaw " << yaw;
  }
}

// 10 mm range noise, 0.5 m away (the Table 1 setting): over 200 draws the mean error along the
// view ray (the bias) stays below 1.5 mm for both shapes; a point-to-surface fit of a 13 mm
// circle under 10 mm noise is pulled toward the sensor.
TEST(LegFitTest, NoisyRangesGiveNoBiasAlongTheBeam) {
  const LegFitConfig config;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> noise(0.0, 0.01);
  const Eigen::Vector2d c(0.5, 0.05);
  const Eigen::Vector2d view = c.normalized();
  for (const auto& leg : {Round26(), Square40()}) {
    double sum_radial = 0.0;
    constexpr int kDraws = 200;
    for (int k = 0; k < kDraws; ++k) {
      auto pts = leg.shape == geometry::LegShape::kCircle
                     ? testing::CastCircle(c, leg.Radius(), kAlpha)
                     : testing::CastBox(geometry::Pose2(c.x(), c.y(), 0.0), 0.04, 0.04, kAlpha);
      for (auto& q : pts) {
        q.range += noise(rng);
        q.p = q.range * Eigen::Vector2d(std::cos(q.angle), std::sin(q.angle));
      }
      sum_radial += (FitLeg(pts, leg, 0.0, config).centre - c).dot(view);
    }
    EXPECT_LT(std::abs(sum_radial / kDraws), 1.5e-3);
  }
}

// 10 mm range noise, 1 m away, the beams at a random phase to the leg: the centre across the
// beam comes from the silhouette (the bearings of the outer beams), not from the noisy ranges.
// Its RMS error stays within 0.35 beam steps (quantisation of both edges alone: 0.2 steps); with
// the silhouette term off, range noise leaks across the beam (round 0.7 steps, box 0.4).
TEST(LegFitTest, NoisyRangesLeaveTheCentreOnTheSilhouetteBisector) {
  std::mt19937_64 rng(2);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::uniform_real_distribution<double> phase(0.0, kAlpha);
  for (const auto& leg : {Round26(), Square40()}) {
    for (const double sigma_beams : {0.3, 1e6}) {
      LegFitConfig config;
      config.silhouette_sigma_beams = sigma_beams;
      double sum_sq = 0.0;
      constexpr int kDraws = 300;
      for (int k = 0; k < kDraws; ++k) {
        const double bearing = 0.2 + phase(rng);
        const Eigen::Vector2d c(std::cos(bearing), std::sin(bearing));
        auto pts = leg.shape == geometry::LegShape::kCircle
                       ? testing::CastCircle(c, leg.Radius(), kAlpha)
                       : testing::CastBox(geometry::Pose2(c.x(), c.y(), 0.5), 0.04, 0.04, kAlpha);
        // The helpers start at the left tangent; beams of a real scan fall at any phase.
        const double shift = phase(rng);
        for (auto& q : pts) {
          q.angle -= shift;
          q.range += noise(rng);
          q.p = q.range * Eigen::Vector2d(std::cos(q.angle), std::sin(q.angle));
        }
        const Eigen::Vector2d truth =
            Eigen::Rotation2Dd(-shift) * c;  // the leg rotated with the beams
        const Eigen::Vector2d e = FitLeg(pts, leg, 0.5, config).centre - truth;
        const double across = truth.x() * e.y() - truth.y() * e.x();
        sum_sq += across * across;
      }
      const double rms_steps = std::sqrt(sum_sq / kDraws) / kAlpha;
      std::printf("[ leg fit ] %s silhouette sigma %g beams: RMS across the beam %.2f steps\n",
                  leg.shape == geometry::LegShape::kCircle ? "round" : "box", sigma_beams,
                  rms_steps);
      if (sigma_beams < 1.0) {
        EXPECT_LT(rms_steps, 0.35);
      }
    }
  }
}

TEST(LegFitTest, OnePointAndNoPoint) {
  const LegFitConfig config;
  EXPECT_FALSE(FitLeg({}, Square40(), 0.0, config).converged);
  // One beam straight at a box face 2 m away: the centre lies half a leg behind the point.
  const ScanPoint q{Eigen::Vector2d(2.0, 0.0), 2.0, 0.0, 0};
  const LegFitResult r = FitLeg({q}, Square40(), 0.0, config);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.centre.x(), 2.02, 1e-3);
  EXPECT_NEAR(r.centre.y(), 0.0, 1e-3);
}

}  // namespace
}  // namespace shelfdock::perception
