// Re-measuring a tracked shelf from the legs the scan shows where they are expected: the robot on
// the final straight sees only the two far legs. Scenes from the simulated WLR-716 (10 mm noise,
// mixed points); every pose compared with the simulated truth.
#include "perception/known_legs.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "geometry/angle.hpp"
#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

using testing::PaperModels;
using testing::SimScan;

// Tolerances: 2 legs at 0.6-0.8 m, 10 mm range noise, each fitted centre within ~4 mm (the
// declared leg_sigma_m): heading std about 4 mm * sqrt(2) / 0.856 m = 6.6 mrad, the centre 0.54 m
// from the legs' midpoint across that lever. Each error must lie within the result's own
// covariance (squared Mahalanobis distance below 16.3, chi-square 3 dof at 99.9 %), and on
// average near its expectation (3; below 6 over 20 scans).
constexpr double kMaxMahalanobis2 = 16.3;
constexpr double kMaxMeanMahalanobis2 = 6.0;

// The sensor 0.2 m behind the centre of a 1080x856 shelf, looking along its long side: the far
// legs 0.74 m ahead at about +-35 degrees, the near legs behind the sensor's field of view.
struct InsideScene {
  geometry::ShelfModel model = PaperModels()[3];
  geometry::Pose2 truth{0.2, 0.01, 0.02};  // shelf in the lidar frame
  std::array<bool, 4> far_legs{};

  InsideScene() {
    const auto corners = model.LegCentres();
    for (std::size_t k = 0; k < 4; ++k) far_legs[k] = (truth * corners[k]).x() > 0.0;
  }
  std::vector<ScanPoint> Points(int seed) const {
    sim::World world;
    testing::AddRoom(world);
    world.AddShelf(1, model, truth);
    return ScanToPoints(SimScan(world, {}, seed));
  }
};

TEST(KnownLegsTest, TwoFarLegsGiveThePoseFromAPriorACentimetreOff) {
  const InsideScene scene;
  ASSERT_EQ(std::count(scene.far_legs.begin(), scene.far_legs.end(), true), 2);
  // As the fused estimate is on the final straight: within a centimetre and a few mrad.
  const geometry::Pose2 prior = scene.truth * geometry::Pose2(0.01, -0.006, 0.005);
  double sum_m2 = 0.0;
  constexpr int kScans = 20;
  for (int seed = 1; seed <= kScans; ++seed) {
    const auto r = MeasureKnownLegs(scene.Points(seed), prior, scene.model, scene.far_legs);
    ASSERT_TRUE(r) << "seed " << seed;
    EXPECT_EQ(r->legs, 2);
    const Eigen::Vector3d e(r->T_lidar_shelf.x - scene.truth.x, r->T_lidar_shelf.y - scene.truth.y,
                            geometry::AngleDiff(r->T_lidar_shelf.yaw, scene.truth.yaw));
    const double m2 = e.dot(r->covariance.inverse() * e);
    EXPECT_LT(m2, kMaxMahalanobis2) << "seed " << seed << " error " << e.transpose();
    sum_m2 += m2;
    // The covariance is a covariance: symmetric, positive definite, heading from the legs'
    // spread (4 mm over 0.856 m: ~6.6 mrad).
    EXPECT_TRUE(r->covariance.isApprox(r->covariance.transpose()));
    EXPECT_GT(r->covariance.determinant(), 0.0);
    EXPECT_NEAR(std::sqrt(r->covariance(2, 2)), 0.004 * std::sqrt(2.0) / 0.856, 1e-4);
  }
  EXPECT_LT(sum_m2 / kScans, kMaxMeanMahalanobis2);
}

TEST(KnownLegsTest, OneLegOrLegsThatAreNotThereGiveNothing) {
  const InsideScene scene;
  const std::vector<ScanPoint> points = scene.Points(3);
  std::array<bool, 4> one{};
  for (std::size_t k = 0; k < 4; ++k) {
    if (scene.far_legs[k]) {
      one[k] = true;
      break;
    }
  }
  EXPECT_FALSE(MeasureKnownLegs(points, scene.truth, scene.model, one));
  // A prior 5 cm off: legs found, but farther from where they should be than max_offset_m.
  EXPECT_FALSE(MeasureKnownLegs(points, scene.truth * geometry::Pose2(0.05, 0.0, 0.0), scene.model,
                                scene.far_legs));
  // A prior 0.3 m off: nothing of the shelf within the search radius of the predicted legs.
  EXPECT_FALSE(MeasureKnownLegs(points, scene.truth * geometry::Pose2(0.0, 0.3, 0.0), scene.model,
                                scene.far_legs));
  // The wrong model's corners (1250x1250) do not fit two legs 0.856 m apart.
  EXPECT_FALSE(MeasureKnownLegs(points, scene.truth, PaperModels()[2], scene.far_legs));
}

}  // namespace
}  // namespace shelfdock::perception
