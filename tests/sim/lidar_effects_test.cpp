// The LiDAR's flaws, each switched on alone against an ideal baseline.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

#include "sim/lidar.hpp"

namespace shelfdock::sim {
namespace {

using geometry::Pose2;

/// Counts beams whose range lies strictly between foreground and background, away from both.
int CountTrailing(const geometry::LaserScan& scan, double near_m, double far_m) {
  int n = 0;
  for (double r : scan.ranges) n += std::isfinite(r) && r > near_m + 0.05 && r < far_m - 0.05;
  return n;
}

/// A 4 cm round post `post_m` straight ahead of the sensor, a wall across the view at `wall_m`.
World PostBeforeWall(double post_m, double wall_m) {
  World world;
  world.AddRoundPost(Eigen::Vector2d(post_m, 0.0), 0.02);
  world.AddWall({{wall_m, -20.0}, {wall_m, 20.0}});
  return world;
}

/// An ideal LiDAR but for its 12 mrad footprint: wide enough that the post's edges straddle beams.
LidarConfig WideFootprint() {
  LidarConfig config = IdealLidarConfig();
  config.enable_footprint = true;
  config.beam_divergence_rad = 0.012;
  return config;
}

TEST(LidarEffectsTest, FootprintMakesTrailingPointsAtDepthEdgesOnly) {
  // A 4 cm post 0.3 m ahead of a wall at 2.3 m: the post's two silhouette edges are depth edges
  // closer than a pulse length, so straddling beams blend both surfaces into trailing points.
  constexpr double kPost_m = 2.0, kWall_m = 2.3;
  const World world = PostBeforeWall(kPost_m, kWall_m);
  const LidarConfig config = WideFootprint();
  ASSERT_GT(config.echo_separation_m, kWall_m - kPost_m);
  Lidar with(config, 1);
  Lidar without(IdealLidarConfig(), 1);
  const auto labelled = with.ScanLabelled(
      world, [](double) { return Pose2(); }, 0.0);
  const double near_m = kPost_m - 0.02;
  EXPECT_GE(CountTrailing(labelled.scan, near_m, kWall_m), 1);
  EXPECT_EQ(CountTrailing(without.Scan(world, Pose2()), near_m, kWall_m), 0);
  // Every trailing point sits next to the post: within a few beams of its bearing.
  const std::size_t centre = labelled.scan.NearestBeam(0.0);
  for (std::size_t i = 0; i < labelled.scan.ranges.size(); ++i) {
    const double r = labelled.scan.ranges[i];
    if (std::isfinite(r) && r > near_m + 0.05 && r < kWall_m - 0.05) {
      EXPECT_LE(std::abs(static_cast<long>(i) - static_cast<long>(centre)), 4) << "beam " << i;
      EXPECT_TRUE(labelled.truth[i].mixed);
    }
  }
  // Away from edges the footprint does not bias ranges: a flat wall reads its true distance.
  const std::size_t far = labelled.scan.NearestBeam(0.5);
  EXPECT_NEAR(labelled.scan.ranges[far], kWall_m / std::cos(labelled.scan.BeamAngle(far)), 1e-3);
}

TEST(LidarEffectsTest, DistantBackgroundIsASeparatePulseNotATrailingPoint) {
  // The same post 4 m ahead of the wall: foreground and background pulses are resolved, so a
  // straddling beam reads the post (the first pulse, when it covers enough of the beam) or the
  // wall, never a range in between.
  constexpr double kPost_m = 2.0, kWall_m = 6.0;
  const World world = PostBeforeWall(kPost_m, kWall_m);
  const LidarConfig config = WideFootprint();
  ASSERT_LT(config.echo_separation_m, kWall_m - kPost_m);
  Lidar lidar(config, 1);
  const auto scan = lidar.Scan(world, Pose2());
  EXPECT_EQ(CountTrailing(scan, kPost_m - 0.02, kWall_m), 0);
  // The post is still seen: its centre beam reads its front face.
  EXPECT_NEAR(scan.ranges[scan.NearestBeam(0.0)], kPost_m - 0.02, 2e-3);
}

TEST(LidarEffectsTest, TheReceiverReportsTheFirstStrongestOrLastPulse) {
  // The post 4 m ahead of the wall again: beams straddling its outline see two pulses. The
  // default receiver reports the post's (first), a last-echo receiver the wall's on those
  // beams, and a strongest-echo one the post's, nine times nearer and as bright (1 / r^2).
  constexpr double kPost_m = 2.0, kWall_m = 6.0;
  const World world = PostBeforeWall(kPost_m, kWall_m);
  LidarConfig config = WideFootprint();
  config.min_echo_fraction = 0.2;  // both pulses of an edge beam count
  auto scan_with = [&](EchoChoice choice) {
    LidarConfig c = config;
    c.echo_choice = choice;
    return Lidar(c, 1).Scan(world, Pose2());
  };
  const auto first = scan_with(EchoChoice::kFirst);
  const auto last = scan_with(EchoChoice::kLast);
  const auto strongest = scan_with(EchoChoice::kStrongest);
  const std::size_t centre = first.NearestBeam(0.0);
  int on_post = 0, post_to_wall = 0;
  for (std::size_t i = centre - 6; i <= centre + 6; ++i) {
    const bool post = std::abs(first.ranges[i] - kPost_m) < 0.03;
    on_post += post;
    // Every beam reads one surface or the other, never a range between them.
    for (const auto* scan : {&first, &last, &strongest}) {
      const double r = scan->ranges[i];
      const double wall = kWall_m / std::cos(scan->BeamAngle(i));
      EXPECT_TRUE(std::abs(r - kPost_m) < 0.03 || std::abs(r - wall) < 1e-3) << "beam " << i;
    }
    EXPECT_DOUBLE_EQ(strongest.ranges[i], first.ranges[i]) << "beam " << i;
    if (post && std::abs(last.ranges[i] - kPost_m) >= 0.03) ++post_to_wall;
  }
  EXPECT_GE(on_post, 2);
  // The outline's edge beams go to the wall for the last-echo receiver; its middle stays.
  EXPECT_GE(post_to_wall, 1);
  EXPECT_LT(post_to_wall, on_post);
  EXPECT_NEAR(last.ranges[centre], kPost_m - 0.02, 2e-3);
}

TEST(LidarEffectsTest, MotionSkewMatchesSpeedTimesSweepTime) {
  // A room seen by a LiDAR driving +x at 0.4 m/s. Reconstructing each point from the pose at
  // the scan's start misplaces beam i by v * t_i: 2.7 cm for the last beam at 15 Hz.
  World world;
  world.AddWall({{-5.0, -5.0}, {5.0, -5.0}, {5.0, 5.0}, {-5.0, 5.0}}, true);
  const double v = 0.4;
  Lidar lidar(IdealLidarConfig(), 1);
  const auto pose_at = [v](double t) { return Pose2(v * t, 0.0, 0.0); };
  const auto scan = lidar.Scan(world, pose_at, 0.0);
  const double expected_skew = v / 15.0;
  EXPECT_NEAR(v * (scan.ranges.size() - 1) * scan.time_increment, expected_skew, 1e-12);
  EXPECT_NEAR(expected_skew, 0.0267, 1e-4);
  for (std::size_t i = 0; i < scan.ranges.size(); i += 20) {
    const double t = i * scan.time_increment;
    const double a = scan.BeamAngle(i);
    // With the true pose at the firing time the point lies exactly on the room's walls ...
    const Eigen::Vector2d p_true =
        pose_at(t) * Eigen::Vector2d(scan.ranges[i] * std::cos(a), scan.ranges[i] * std::sin(a));
    EXPECT_NEAR(std::max(std::abs(p_true.x()), std::abs(p_true.y())), 5.0, 1e-9);
    // ... and it is the pose at t, not at 0, that explains it: the skew is v * t.
    const Eigen::Vector2d p_static(scan.ranges[i] * std::cos(a), scan.ranges[i] * std::sin(a));
    EXPECT_NEAR((p_true - p_static).norm(), v * t, 1e-9);
  }
}

TEST(LidarEffectsTest, TiltedScanPlaneHitsTheFloorAtHeightOverTanTilt) {
  World world;  // an empty floor
  LidarConfig config = IdealLidarConfig();
  config.enable_tilt = true;
  config.mount_height_m = 0.2;
  config.tilt_pitch_rad = geometry::DegToRad(1.0);  // nose down
  Lidar lidar(config, 1);
  const auto scan = lidar.Scan(world, Pose2());
  // Straight ahead the beam sinks by the full tilt: floor at h / tan(tilt) horizontally,
  // h / sin(tilt) along the beam (11.46 m for 0.2 m and 1 deg).
  EXPECT_NEAR(scan.ranges[scan.NearestBeam(0.0)], 0.2 / std::sin(config.tilt_pitch_rad), 1e-6);
  // At 60 deg the depression is asin(sin(tilt) cos 60): the floor is twice as far.
  const std::size_t i60 = scan.NearestBeam(std::numbers::pi / 3);
  const double depression =
      std::asin(std::sin(config.tilt_pitch_rad) * std::cos(scan.BeamAngle(i60)));
  EXPECT_NEAR(scan.ranges[i60], 0.2 / std::sin(depression), 1e-6);
  // Sideways the beam stays level and backwards it climbs: no floor there.
  EXPECT_TRUE(std::isnan(scan.ranges[scan.NearestBeam(std::numbers::pi / 2)]));
  EXPECT_TRUE(std::isnan(scan.ranges.front()));
}

TEST(LidarEffectsTest, TiltCutsObjectsAtAnotherHeight) {
  // A 10 cm high box 3 m ahead is under a level 20 cm scan plane, but a beam pitched 3 deg
  // down is 20 - 300 tan 3 deg = 4.3 cm high there and hits it.
  World world;
  Box low;
  low.T_world_box = Pose2(3.25, 0.0, 0.0);
  low.length_m = 0.5;
  low.height_m = 0.1;
  world.AddBox(low);
  LidarConfig level = IdealLidarConfig();
  LidarConfig tilted = level;
  tilted.enable_tilt = true;
  tilted.tilt_pitch_rad = geometry::DegToRad(3.0);
  Lidar a(level, 1), b(tilted, 1);
  const auto sa = a.Scan(world, Pose2());
  const auto sb = b.Scan(world, Pose2());
  EXPECT_TRUE(std::isnan(sa.ranges[sa.NearestBeam(0.0)]));
  EXPECT_NEAR(sb.ranges[sb.NearestBeam(0.0)], 3.0 / std::cos(tilted.tilt_pitch_rad), 1e-6);
}

TEST(LidarEffectsTest, YawOffsetRotatesWhatTheScanShows) {
  World world;
  world.AddRoundPost(Eigen::Vector2d(3.0, 0.0), 0.03);
  LidarConfig config = IdealLidarConfig();
  config.yaw_offset_rad = 0.02;  // beams really leave 20 mrad further CCW than reported
  config.yaw_offset_rad = 0.02;
  Lidar lidar(config, 1);
  const auto scan = lidar.Scan(world, Pose2());
  // The post at true bearing 0 shows at reported bearing -0.02 rad.
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (std::isfinite(scan.ranges[i])) {
      sum += scan.BeamAngle(i);
      ++n;
    }
  }
  ASSERT_GT(n, 0);
  EXPECT_NEAR(sum / n, -0.02, scan.angle_increment);
}

TEST(LidarEffectsTest, DarkSurfacesDropMoreBeams) {
  World world;
  Wall bright;
  bright.points = {{3.0, 0.0}, {3.0, 20.0}};
  bright.material.reflectivity = 0.9;
  Wall dark;
  dark.points = {{3.0, -20.0}, {3.0, 0.0}};
  dark.material.reflectivity = 0.05;
  world.AddWall(bright);
  world.AddWall(dark);
  LidarConfig config = IdealLidarConfig();
  config.enable_dropouts = true;
  config.dropout_probability = 0.0;
  config.dark_dropout_gain = 0.2;
  Lidar lidar(config, 5);
  int dark_drops = 0, bright_drops = 0, dark_n = 0, bright_n = 0;
  for (int k = 0; k < 20; ++k) {
    const auto scan = lidar.Scan(world, Pose2());
    for (std::size_t i = scan.NearestBeam(-1.2); i <= scan.NearestBeam(1.2); ++i) {
      const bool is_dark = scan.BeamAngle(i) < -0.01;
      const bool is_bright = scan.BeamAngle(i) > 0.01;
      if (is_dark) ++dark_n, dark_drops += std::isnan(scan.ranges[i]);
      if (is_bright) ++bright_n, bright_drops += std::isnan(scan.ranges[i]);
    }
  }
  // Expected rates: 0.2 * (1 - 0.05) = 0.19 and 0.2 * (1 - 0.9) = 0.02.
  EXPECT_NEAR(static_cast<double>(dark_drops) / dark_n, 0.19, 0.03);
  EXPECT_NEAR(static_cast<double>(bright_drops) / bright_n, 0.02, 0.01);
}

// Stray echoes (stray_probability 0.2): about a fifth of the beams, each flagged in the truth,
// return short of what the beam saw, uniformly (mean halfway to the wall 4 m ahead, within 0.1 m),
// and the beams that see nothing (behind the sensor) return strays short of range_max_m as
// often. Switched off (the default, and IdealLidarConfig), no beam is a stray.
TEST(LidarEffectsTest, StrayEchoesComeShortOfWhatTheBeamSaw) {
  World world;
  Wall wall;
  wall.points = {{4.0, -20.0}, {4.0, 20.0}};
  world.AddWall(wall);
  LidarConfig config = IdealLidarConfig();
  config.range_max_m = 10.0;
  config.stray_probability = 0.2;
  Lidar lidar(config, 11);
  int wall_beams = 0, strays = 0, open_beams = 0, open_strays = 0;
  double sum_fraction = 0.0;
  for (int k = 0; k < 20; ++k) {
    const LabelledScan out = lidar.ScanLabelled(
        world, [](double) { return Pose2(); }, 0.0);
    for (std::size_t i = 0; i < out.scan.ranges.size(); ++i) {
      const double angle = out.scan.BeamAngle(i);
      if (std::abs(angle) > 2.0) {  // no wall there: nothing within range
        ++open_beams;
        if (out.truth[i].stray) {
          ++open_strays;
          EXPECT_LE(out.scan.ranges[i], config.range_max_m);
        } else {
          EXPECT_TRUE(std::isnan(out.scan.ranges[i]));
        }
        continue;
      }
      if (std::abs(angle) > 1.0) continue;  // the wall within range_max_m
      ++wall_beams;
      const double own = 4.0 / std::cos(angle);
      if (!out.truth[i].stray) {
        EXPECT_NEAR(out.scan.ranges[i], own, 1e-6);
        continue;
      }
      ++strays;
      EXPECT_GE(out.scan.ranges[i], config.range_min_m - 1e-9);
      EXPECT_LE(out.scan.ranges[i], own + 1e-9);
      sum_fraction += out.scan.ranges[i] / own;
    }
  }
  EXPECT_NEAR(static_cast<double>(strays) / wall_beams, 0.2, 0.02);
  EXPECT_NEAR(static_cast<double>(open_strays) / open_beams, 0.2, 0.03);
  EXPECT_NEAR(sum_fraction / strays, 0.5, 0.05);

  LidarConfig off = config;
  off = IdealLidarConfig(off);
  Lidar a(off, 3);
  const LabelledScan clean = a.ScanLabelled(
      world, [](double) { return Pose2(); }, 0.0);
  for (const BeamTruth& t : clean.truth) EXPECT_FALSE(t.stray);
}

// A systematic range error (LidarConfig::range_bias_m): every return on a wall 3 m ahead reads
// the true range plus the bias, either sign, and the truth keeps the true range.
TEST(LidarEffectsTest, ARangeBiasMovesEveryReturnAlongItsBeam) {
  World world;
  Wall wall;
  wall.points = {{3.0, -10.0}, {3.0, 10.0}};
  world.AddWall(wall);
  for (const double bias : {0.02, -0.015}) {
    SCOPED_TRACE(bias);
    LidarConfig config = IdealLidarConfig();
    config.range_bias_m = bias;
    Lidar lidar(config, 5);
    const LabelledScan out = lidar.ScanLabelled(
        world, [](double) { return Pose2(); }, 0.0);
    int wall_beams = 0;
    for (std::size_t i = 0; i < out.scan.ranges.size(); ++i) {
      const double angle = out.scan.BeamAngle(i);
      if (std::abs(angle) > 1.0) continue;
      ++wall_beams;
      const double own = 3.0 / std::cos(angle);
      EXPECT_NEAR(out.scan.ranges[i], own + bias, 1e-6);
      EXPECT_NEAR(out.truth[i].true_range_m, own, 1e-6);
    }
    EXPECT_GT(wall_beams, 300);
  }
  // IdealLidarConfig switches it off.
  LidarConfig biased;
  biased.range_bias_m = 0.02;
  EXPECT_EQ(IdealLidarConfig(biased).range_bias_m, 0.0);
}

TEST(LidarEffectsTest, IntensityFollowsReflectivityAndRange) {
  World world;
  Wall bright;
  bright.points = {{2.0, 0.0}, {2.0, 5.0}};
  bright.material.reflectivity = 0.8;
  Wall dark;
  dark.points = {{2.0, -5.0}, {2.0, 0.0}};
  dark.material.reflectivity = 0.2;
  world.AddWall(bright);
  world.AddWall(dark);
  LidarConfig config = IdealLidarConfig();
  config.intensity_noise_rel = 0.0;
  Lidar lidar(config, 1);
  const auto scan = lidar.Scan(world, Pose2());
  const double a = 0.2;  // symmetric beams: same range and incidence, 4x the reflectivity
  const double ib = scan.intensities[scan.NearestBeam(a)];
  const double id = scan.intensities[scan.NearestBeam(-a)];
  EXPECT_GT(id, 0.0);
  EXPECT_NEAR(ib / id, 4.0, 1e-6);
}

TEST(LidarEffectsTest, PeopleWalkDuringTheScan) {
  World world;
  Person person;
  person.path.waypoints = {{3.0, -5.0}, {3.0, 5.0}};  // crossing in front, 1 m/s
  person.path.speed_mps = 1.0;
  world.AddPerson(person);
  Lidar lidar(IdealLidarConfig(), 1);
  auto centroid_y = [](const geometry::LaserScan& s) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < s.ranges.size(); ++i) {
      if (!std::isfinite(s.ranges[i])) continue;
      sum += s.ranges[i] * std::sin(s.BeamAngle(i));
      ++n;
    }
    return n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
  };
  // At t = 5 s the person is at y = 0, at t = 6 s at y = 1: the legs moved about 1 m.
  const double y5 = centroid_y(lidar.Scan(world, Pose2(), 5.0));
  const double y6 = centroid_y(lidar.Scan(world, Pose2(), 6.0));
  EXPECT_NEAR(y6 - y5, 1.0, 0.25);
}

}  // namespace
}  // namespace shelfdock::sim
