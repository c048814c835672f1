// FitShelfToReturns against simulated ground truth: the shelf fitted to its legs' returns at
// once, beside the two-stage fit the paper describes (each leg alone, then the shelf to the leg
// centres, RefineShelfPose).
#include "perception/shelf_return_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "perception/leg_fit.hpp"
#include "perception/preprocess.hpp"
#include "perception/shelf_fit.hpp"
#include "perception/silhouette_edges.hpp"
#include "scene_builder.hpp"
#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kRangeNoise = 0.02;  // [m] range noise of the simulated scans

// One simulated scan of a shelf, its legs' returns cut by the truth (returns within the leg's
// half diagonal plus 2 cm of its centre), as the detector's clusters would hold them.
struct ShelfScan {
  std::vector<ScanPoint> points;             // every valid return, beam order
  std::vector<std::vector<ScanPoint>> legs;  // returns of each leg seen
  std::vector<SilhouetteEdges> edges;        // their outlines
  std::array<Eigen::Vector2d, 4> centres{};  // each leg's own fit (FitLeg)
  int count = 0;                             // legs seen (3 or 4 are used)
};

// The WLR-716 defaults but for the noise.
sim::LidarConfig NoisyWlr() {
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = kRangeNoise;
  return lidar;
}

// A blooming receiver: 10 mm noise, 9 mrad beams of 15 footprint rays, any echo returned (a beam
// returns a thin leg it only grazes with its spot).
sim::LidarConfig BloomingWlr() {
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = 0.01;
  lidar.beam_divergence_rad = 0.009;
  lidar.footprint_rays = 15;
  lidar.min_echo_fraction = 0.01;
  return lidar;
}

ShelfScan ScanShelf(const geometry::ShelfModel& model, const geometry::Pose2& truth,
                    std::uint64_t seed, const sim::LidarConfig& lidar = NoisyWlr()) {
  sim::World world;
  testing::AddRoom(world);
  world.AddShelf(1, model, truth);
  ShelfScan s;
  s.points = ScanToPoints(testing::SimScan(world, {}, seed, lidar));
  const double reach = 0.5 * std::hypot(model.leg.length_m, model.leg.width_m) + 0.02;
  const auto corners = model.LegCentres();
  auto seen = [&](int k) {
    const Eigen::Vector2d centre = truth * corners[static_cast<std::size_t>(k)];
    return std::any_of(s.points.begin(), s.points.end(),
                       [&](const ScanPoint& q) { return (q.p - centre).norm() < reach; });
  };
  // Cyclic order as a LegSet holds it; with a leg hidden, the corner opposite it in the middle.
  int first = 0;
  for (int k = 0; k < 4; ++k) {
    if (!seen(k)) first = k + 1;
  }
  for (int j = 0; j < 4; ++j) {
    const Eigen::Vector2d centre = truth * corners[static_cast<std::size_t>((first + j) % 4)];
    std::vector<ScanPoint> leg;
    for (const ScanPoint& q : s.points) {
      if ((q.p - centre).norm() < reach) leg.push_back(q);
    }
    if (leg.empty() || s.count == 4) continue;
    s.edges.push_back(FindSilhouetteEdges(s.points, leg.front(), leg.back(), 0.1));
    s.centres[s.count] = FitLeg(leg, model.leg, truth.yaw, LegFitConfig{}, s.edges.back()).centre;
    s.legs.push_back(std::move(leg));
    ++s.count;
  }
  return s;
}

// The two-stage fit as the detector makes it: FitShelf, then RefineShelfPose with each leg's
// std along its beam (range noise over the root of its returns) and across it (a beam step's
// quantisation over the same root).
std::optional<std::pair<ShelfFitResult, ShelfRefineResult>> FitLegCentres(
    const ShelfScan& s, const geometry::ShelfModel& model) {
  const auto fit = FitShelf(s.centres, s.count, model, ShelfFitConfig{});
  if (!fit) return std::nullopt;
  std::array<LegSigma, 4> sigma{};
  for (int i = 0; i < s.count; ++i) {
    const double n = static_cast<double>(s.legs[i].size());
    const double step = s.centres[i].norm() * testing::kWlrAlpha;
    sigma[i].along_m = std::sqrt(kRangeNoise * kRangeNoise / n + 1e-6);
    sigma[i].across_m = std::sqrt(step * step / 12.0 / n + 1e-6);
  }
  return std::pair{*fit, RefineShelfPose(s.centres, s.count, model, *fit, sigma)};
}

std::vector<LegReturns> Returns(const ShelfScan& s, const ShelfFitResult& fit,
                                double range_noise_m = kRangeNoise) {
  std::vector<LegReturns> out;
  for (int i = 0; i < s.count; ++i) {
    LegReturns r;
    r.corner = fit.corner_of_leg[i];
    r.points = &s.legs[i];
    r.silhouette = MakeSilhouetteTerm(s.legs[i], s.edges[i], LegFitConfig{});
    r.range_sigma_m = range_noise_m;
    out.push_back(r);
  }
  return out;
}

// Pose errors of the fits on the returns and on the leg centres over a sweep of scans.
struct SweepErrors {
  double centre2_returns = 0.0, centre2_legs = 0.0, yaw2_returns = 0.0, yaw2_legs = 0.0;
  int fitted = 0;

  // Adds one scan's two poses; the returns' centre and heading errors.
  std::pair<double, double> Add(const geometry::Pose2& on_returns, const geometry::Pose2& on_legs,
                                const geometry::Pose2& truth, const geometry::ShelfModel& model) {
    const double e = geometry::Distance(on_returns, truth);
    const double y = testing::SymmetricYawError(on_returns.yaw, truth.yaw, model);
    const double e_legs = geometry::Distance(on_legs, truth);
    const double y_legs = testing::SymmetricYawError(on_legs.yaw, truth.yaw, model);
    centre2_returns += e * e;
    yaw2_returns += y * y;
    centre2_legs += e_legs * e_legs;
    yaw2_legs += y_legs * y_legs;
    ++fitted;
    return {e, std::abs(y)};
  }

  // Prints the RMS errors and expects the fit on the returns the better on both.
  void ExpectReturnsBetter() const {
    const double n = static_cast<double>(fitted);
    std::printf("%d scans: RMS centre %.1f / %.1f mm, heading %.1f / %.1f mrad (returns / legs)\n",
                fitted, 1e3 * std::sqrt(centre2_returns / n), 1e3 * std::sqrt(centre2_legs / n),
                1e3 * std::sqrt(yaw2_returns / n), 1e3 * std::sqrt(yaw2_legs / n));
    EXPECT_LT(centre2_returns, centre2_legs);
    EXPECT_LT(yaw2_returns, yaw2_legs);
  }
};

// A 1075 x 883 shelf 3.0-3.4 m out (its far legs 3.8-4.4 m, one to three returns each), turned
// every way, 20 mm range noise (the noisier sensor), 200 seeds. Fitted each alone, a far
// leg of one or two returns may sit anywhere along the face they hit, and its range follows; on
// the returns at once the other legs hold it. Measured over the 200 scans: RMS centre error
// 6.3 mm on the returns against 6.8 mm on the leg centres, heading 5.2 against 5.9 mrad (at 10 mm
// noise the two differ by less than 10 %, the returns' fit the worse: 4.8 against 4.6 mm over 40
// such scans; eval-layouts shows the same, 20 mm scenes gain and 10 mm ones barely move). Asserted:
// every pose on the returns within 30 mm / 30 mrad of the truth, and both RMS errors below the
// two-stage fit's.
TEST(ShelfReturnFitTest, FarLegsSeenByFewReturnsAreHeldWhereTheOtherLegsPutThem) {
  const auto model = testing::PaperModels()[1];
  SweepErrors errors;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const double standoff = 3.0 + 0.1 * static_cast<double>(seed % 5);
    const double bearing = -0.6 + 0.03 * static_cast<double>(seed % 40);
    const double yaw = 0.157 * static_cast<double>(seed);
    const geometry::Pose2 truth = testing::PlaceShelf(model, standoff, bearing, yaw);
    const ShelfScan s = ScanShelf(model, truth, seed);
    if (s.count < 3) continue;
    const auto legs_fit = FitLegCentres(s, model);
    ASSERT_TRUE(legs_fit.has_value()) << seed;
    const ShelfReturnFitResult on_returns = FitShelfToReturns(
        Returns(s, legs_fit->first), model, legs_fit->second.T_lidar_shelf, LegFitConfig{});
    const auto [e, y] =
        errors.Add(on_returns.T_lidar_shelf, legs_fit->second.T_lidar_shelf, truth, model);
    EXPECT_LT(e, 0.03) << seed;
    EXPECT_LT(y, 0.03) << seed;
    EXPECT_GE(on_returns.T_lidar_shelf.yaw, -M_PI);
    EXPECT_LT(on_returns.T_lidar_shelf.yaw, M_PI);
  }
  ASSERT_GE(errors.fitted, 150);
  errors.ExpectReturnsBetter();
}

// A 1080 x 856 shelf 1.9-2.3 m out and face-on (its heading within 20 mrad of the sensor's axis,
// at bearings within 0.2 rad, so the beams run nearly along its legs' sides), seen by a blooming
// scanner (9 mrad spot, an echo from 1 % of it: config/lidar_variants/bloom.yaml) at
// 10 mm range noise, 100 seeds: every leg returns a beam or two past its edges at its face's
// range, beams nearly parallel to the leg's side faces that miss the section by a centimetre.
// Measured across the beam (BoxRayResidual) such a return costs its centimetre; measured along
// it, as the slab test's gap did, it counted up to a metre off and turned the shelf (independent
// generator, against_wall seed 1 scene 84: 5 cm and 66 mrad off). Measured over the 100 scans,
// on the returns / on the leg centres: RMS centre 5.6 / 7.6 mm, heading 4.6 / 5.1 mrad, worst
// 14.4 mm and 13.9 mrad; with the slab gap 10.3 / 8.0 mm, 8.0 / 4.5 mrad, worst 43.8 mm and
// 37.8 mrad. Asserted: every pose within 20 mm / 20 mrad of the truth, and the returns' RMS
// errors below the two-stage fit's.
TEST(ShelfReturnFitTest, ReturnsBloomedPastAFaceOnLegsEdgesDoNotTurnTheShelf) {
  const auto model = testing::PaperModels()[3];
  ASSERT_EQ(model.name, "t1-rect-1080x856");
  const sim::LidarConfig bloom = BloomingWlr();
  SweepErrors errors;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const double standoff = 1.9 + 0.1 * static_cast<double>(seed % 5);
    const double bearing = -0.2 + 0.02 * static_cast<double>(seed % 21);
    const double yaw = -0.02 + 0.004 * static_cast<double>(seed % 11);
    const geometry::Pose2 truth = testing::PlaceShelf(model, standoff, bearing, yaw);
    const ShelfScan s = ScanShelf(model, truth, seed, bloom);
    if (s.count < 3) continue;
    const auto legs_fit = FitLegCentres(s, model);
    ASSERT_TRUE(legs_fit.has_value()) << seed;
    const ShelfReturnFitResult on_returns =
        FitShelfToReturns(Returns(s, legs_fit->first, bloom.range_noise_sigma_m), model,
                          legs_fit->second.T_lidar_shelf, LegFitConfig{});
    const auto [e, y] =
        errors.Add(on_returns.T_lidar_shelf, legs_fit->second.T_lidar_shelf, truth, model);
    EXPECT_LT(e, 0.02) << seed;
    EXPECT_LT(y, 0.02) << seed;
  }
  ASSERT_GE(errors.fitted, 90);
  errors.ExpectReturnsBetter();
}

// A 1080 x 856 shelf 2.5-3.3 m out, turned 0.05-0.25 rad from square to the beams, seen by the
// blooming sensor above (9 mrad beams, a 4 mm aperture, 15 footprint rays, any echo returned):
// each leg's side face shows at grazing incidence, so its back corner is the silhouette's edge
// on that side, and beams past it return from the leg's front through their spots. Measured
// against the back corner (no spot), those returns pull the shelf toward the sensor; against the
// nearest corner the sensor's spot reaches (half its divergence and aperture on each side) the
// pull is gone. Over the 100 scans: the centre's error along the line of sight averages -4.1 mm
// without the spot, -0.3 mm with it (RMS centre error 6.2 and 4.9 mm; with half the divergence
// alone, the aperture left out, -1.2 mm). Asserted: with the spot the mean error along the line of
// sight within 1 mm of the truth, and the RMS centre error below the plain fit's.
TEST(ShelfReturnFitTest, ReturnsPastALegsEdgeAreMeasuredWhereItsSpotReaches) {
  const auto model = testing::PaperModels()[3];
  ASSERT_EQ(model.name, "t1-rect-1080x856");
  const sim::LidarConfig bloom = BloomingWlr();
  double along_plain = 0.0, along_spot = 0.0, rms_plain = 0.0, rms_spot = 0.0;
  int fitted = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const double standoff = 2.5 + 0.2 * static_cast<double>(seed % 5);
    const double bearing = -0.2 + 0.02 * static_cast<double>(seed % 21);
    const double turn = 0.05 + 0.02 * static_cast<double>(seed % 11);
    const double yaw = (seed % 2 == 0 ? 1.0 : -1.0) * turn;
    const geometry::Pose2 truth = testing::PlaceShelf(model, standoff, bearing, yaw);
    const ShelfScan s = ScanShelf(model, truth, seed, bloom);
    if (s.count < 3) continue;
    const auto legs_fit = FitLegCentres(s, model);
    ASSERT_TRUE(legs_fit.has_value()) << seed;
    std::vector<LegReturns> returns = Returns(s, legs_fit->first, bloom.range_noise_sigma_m);
    const geometry::Pose2 plain =
        FitShelfToReturns(returns, model, legs_fit->second.T_lidar_shelf, LegFitConfig{})
            .T_lidar_shelf;
    // The spot's half-width as the simulated sensor draws it: half its divergence and half its
    // aperture (4 mm) at the shelf's range.
    const double spot_half_rad =
        0.5 * bloom.beam_divergence_rad + 0.5 * bloom.beam_aperture_m / standoff;
    for (LegReturns& r : returns) r.spot_half_rad = spot_half_rad;
    const geometry::Pose2 spot =
        FitShelfToReturns(returns, model, legs_fit->second.T_lidar_shelf, LegFitConfig{})
            .T_lidar_shelf;
    const Eigen::Vector2d sight = truth.translation().normalized();
    along_plain += sight.dot(plain.translation() - truth.translation());
    along_spot += sight.dot(spot.translation() - truth.translation());
    rms_plain += (plain.translation() - truth.translation()).squaredNorm();
    rms_spot += (spot.translation() - truth.translation()).squaredNorm();
    ++fitted;
  }
  ASSERT_GE(fitted, 90);
  const double n = static_cast<double>(fitted);
  std::printf(
      "%d scans: centre along the line of sight %.2f / %.2f mm, RMS %.2f / %.2f mm "
      "(no spot / spot)\n",
      fitted, 1e3 * along_plain / n, 1e3 * along_spot / n, 1e3 * std::sqrt(rms_plain / n),
      1e3 * std::sqrt(rms_spot / n));
  EXPECT_LT(std::abs(along_spot / n), 0.001);
  EXPECT_LT(rms_spot, rms_plain);
}

// A leg given no model corner (corner -1, the default) cannot be placed: the fit returns the
// pose it was given and an infinite chi-square, which loses every comparison.
TEST(ShelfReturnFitTest, ALegWithoutACornerIsNoFit) {
  const auto model = testing::PaperModels()[1];
  const geometry::Pose2 truth = testing::PlaceShelf(model, 2.0, 0.1, 0.4);
  const ShelfScan s = ScanShelf(model, truth, 7);
  ASSERT_GE(s.count, 3);
  const auto legs_fit = FitLegCentres(s, model);
  ASSERT_TRUE(legs_fit.has_value());
  std::vector<LegReturns> legs = Returns(s, legs_fit->first);
  const ShelfReturnFitResult good =
      FitShelfToReturns(legs, model, legs_fit->second.T_lidar_shelf, LegFitConfig{});
  EXPECT_TRUE(std::isfinite(good.chi2));
  EXPECT_LT(geometry::Distance(good.T_lidar_shelf, truth), 0.03);
  legs[1].corner = -1;
  const geometry::Pose2 start(1.0, 2.0, 0.3);
  const ShelfReturnFitResult bad = FitShelfToReturns(legs, model, start, LegFitConfig{});
  EXPECT_TRUE(std::isinf(bad.chi2));
  EXPECT_EQ(bad.T_lidar_shelf.x, start.x);
  EXPECT_EQ(bad.T_lidar_shelf.y, start.y);
  EXPECT_EQ(bad.T_lidar_shelf.yaw, start.yaw);
}

}  // namespace
}  // namespace shelfdock::perception
