// The fault catalogue (src/eval/fault.cpp) and its injection (src/eval/fault_injector.cpp):
// draws are seeded and inside their stated ranges, the world changes are what each fault says,
// and the sensor faults deliver what they say (late scans late and in order, doubled scans
// twice, slipping odometry over-reports, a localisation jump offsets the estimate).
#include "eval/fault.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "eval/fault_injector.hpp"
#include "io/models_yaml.hpp"
#include "io/scenario_yaml.hpp"

namespace shelfdock::eval {
namespace {

using geometry::Pose2;

sim::Scenario PaperScenario() {
  const std::string root = SHELFDOCK_SOURCE_DIR;
  const auto models = io::ReadShelfModels(root + "/config/models.yaml");
  return io::ReadScenario(root + "/config/scenarios/paper_docking.yaml", models);
}

/// A fault of `kind` with the fields set that the injection tests use.
FaultSpec Fault(FaultKind kind, double start_s = 1.0, double duration_s = 2.0,
                double amount = 0.0) {
  FaultSpec f;
  f.kind = kind;
  f.start_s = start_s;
  f.duration_s = duration_s;
  f.amount = amount;
  return f;
}

geometry::LaserScan ScanStamped(double stamp) {
  geometry::LaserScan scan;
  scan.angle_increment = 0.01;
  scan.range_max = 10.0;
  scan.ranges.assign(100, 2.0);
  scan.stamp = stamp;
  return scan;
}

TEST(FaultDrawTest, SeededAndInsideTheStatedRanges) {
  const FaultDrawConfig c;
  std::map<FaultKind, int> seen;
  for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
    const FaultSpec f = DrawFault(seed, c);
    const FaultSpec again = DrawFault(seed, c);
    ASSERT_EQ(f.kind, again.kind);
    ASSERT_EQ(f.start_s, again.start_s);
    ++seen[f.kind];
    switch (f.kind) {
      case FaultKind::kLidarBlackout:
        EXPECT_GT(f.duration_s, 0.0);
        EXPECT_LE(f.duration_s, c.max_blackout_s);
        break;
      case FaultKind::kLateScans:
        EXPECT_GT(f.amount, 0.0);
        EXPECT_LE(f.amount, c.max_late_s);
        break;
      case FaultKind::kLocalisationJump:
        EXPECT_LE(std::hypot(f.offset.x, f.offset.y), c.max_jump_m + 1e-12);
        break;
      case FaultKind::kShelfDisplaced:
        EXPECT_GE(std::hypot(f.offset.x, f.offset.y), c.min_displacement_m - 1e-12);
        EXPECT_LE(std::hypot(f.offset.x, f.offset.y), c.max_displacement_m + 1e-12);
        break;
      case FaultKind::kCameraPartial:
        EXPECT_LE(f.amount, c.max_partial_share);
        break;
      default:
        break;
    }
  }
  // The kinds take turns: each is drawn equally often.
  ASSERT_EQ(seen.size(), AllFaultKinds().size());
  for (const auto& [kind, n] : seen) {
    EXPECT_EQ(n, 3000 / static_cast<int>(AllFaultKinds().size())) << ToString(kind);
  }
}

TEST(FaultDrawTest, TheRuleSaysWhichFaultsLeaveDockingPossible) {
  for (FaultKind kind : AllFaultKinds()) {
    FaultSpec f;
    f.kind = kind;
    const bool impossible = kind == FaultKind::kShelfDisplaced || kind == FaultKind::kNoShelf ||
                            kind == FaultKind::kWrongShelfCode || kind == FaultKind::kCameraBlind ||
                            kind == FaultKind::kPersonStanding;
    EXPECT_EQ(DockingPossible(f), !impossible) << ToString(kind);
    EXPECT_EQ(ExpectedFailures(kind).empty(), !impossible) << ToString(kind);
    // Only a person standing in the path leaves another way in (the shelf's other end); the
    // shelf elsewhere, absent or wrong, or a blind camera, leave none.
    EXPECT_EQ(SuccessAcceptable(kind), kind == FaultKind::kPersonStanding) << ToString(kind);
  }
}

TEST(FaultScenarioTest, NoShelfWrongCodeAndDisplacedShelf) {
  const sim::Scenario base = PaperScenario();
  const int id = base.target_shelf_id;
  const Pose2 truth = base.world.Shelf(id)->T_world_shelf;

  sim::Scenario none = base;
  ApplyFaultToScenario(Fault(FaultKind::kNoShelf), 4.5, &none);
  EXPECT_FALSE(none.world.Shelf(id));

  sim::Scenario wrong = base;
  ApplyFaultToScenario(Fault(FaultKind::kWrongShelfCode), 4.5, &wrong);
  EXPECT_FALSE(wrong.world.Shelf(id));
  ASSERT_EQ(wrong.world.shelves().size(), base.world.shelves().size());
  const sim::ShelfInstance& other = wrong.world.shelves().back();
  EXPECT_NE(other.id, id);
  EXPECT_NEAR(geometry::Distance(other.T_world_shelf, truth), 0.0, 1e-12);

  FaultSpec moved = Fault(FaultKind::kShelfDisplaced);
  moved.offset = Pose2(1.0, -1.0, 0.2);
  sim::Scenario displaced = base;
  ApplyFaultToScenario(moved, 4.5, &displaced);
  const Pose2 now = displaced.world.Shelf(id)->T_world_shelf;
  EXPECT_NEAR(now.x - truth.x, 1.0, 1e-12);
  EXPECT_NEAR(now.y - truth.y, -1.0, 1e-12);
  EXPECT_NEAR(now.yaw - truth.yaw, 0.2, 1e-12);
}

TEST(FaultScenarioTest, MoversCrossTheDockingPathInFrontOfTheShelf) {
  const sim::Scenario base = PaperScenario();
  const sim::ScenarioShelf& shelf = *base.FindShelf(base.target_shelf_id);
  const Pose2 preset = *shelf.T_map_shelf_preset;
  FaultSpec f = Fault(FaultKind::kPersonCrossing);
  f.across_m = 1.5;
  f.speed_mps = 1.0;
  sim::Scenario s = base;
  ApplyFaultToScenario(f, 4.5, &s);
  ASSERT_EQ(s.world.people().size(), 1u);
  // The robot starts west of the shelf: the crossing is 4.5 - 1.5 = 3 m west of the preset, on
  // a path across the shelf's long axis.
  const auto& path = s.world.people().front().path.waypoints;
  const Eigen::Vector2d mid = 0.5 * (path.front() + path.back());
  EXPECT_NEAR(mid.x(), preset.x - 3.0 * std::cos(preset.yaw), 1e-9);
  EXPECT_NEAR(mid.y(), preset.y - 3.0 * std::sin(preset.yaw), 1e-9);
  const Eigen::Vector2d across = path.back() - path.front();
  EXPECT_NEAR(across.dot(Eigen::Vector2d(std::cos(preset.yaw), std::sin(preset.yaw))), 0.0, 1e-9);

  f.kind = FaultKind::kRobotPassing;
  sim::Scenario r = base;
  ApplyFaultToScenario(f, 4.5, &r);
  EXPECT_EQ(r.world.robots().size(), 1u);
}

/// Feeds one scan at each of `scan_steps` (control steps of 0.02 s from t = 0, entry at t = 0)
/// and returns the stamps delivered at each step (-1: none).
std::vector<double> Deliveries(FaultInjector& inj, const std::vector<int>& scan_steps, int steps) {
  std::vector<double> out;
  geometry::LaserScan source;
  for (int k = 0; k < steps; ++k) {
    const double t = 0.02 * k;
    sim::SensorReadings readings;
    if (std::find(scan_steps.begin(), scan_steps.end(), k) != scan_steps.end()) {
      source = ScanStamped(t);
      readings.scan = &source;
    }
    docking::Observations obs;
    inj.Apply(t, t, &readings, &obs);
    out.push_back(readings.scan != nullptr ? readings.scan->stamp : -1.0);
  }
  return out;
}

TEST(FaultInjectorTest, LateScansArriveLateAndInOrder) {
  FaultInjector inj(Fault(FaultKind::kLateScans, 0.0, 0.1, 0.09), 1);
  const std::vector<double> got = Deliveries(inj, {0, 3, 20}, 30);
  // Scans at 0 and 0.06 s are held 0.09 s (to steps 5 and 8); the one at 0.4 s (after the
  // window) is not late.
  for (int k = 0; k < 30; ++k) {
    const double expected = k == 5 ? 0.0 : k == 8 ? 0.06 : k == 20 ? 0.4 : -1.0;
    EXPECT_NEAR(got[k], expected, 1e-9) << "step " << k;
  }
}

TEST(FaultInjectorTest, DoubledScansArriveTwice) {
  FaultInjector inj(Fault(FaultKind::kDoubleScans, 0.0, 0.2), 1);
  const std::vector<double> got = Deliveries(inj, {0, 5}, 8);
  EXPECT_NEAR(got[0], 0.0, 1e-12);
  EXPECT_NEAR(got[1], 0.0, 1e-12);
  EXPECT_NEAR(got[5], 0.1, 1e-12);
  EXPECT_NEAR(got[6], 0.1, 1e-12);
  EXPECT_EQ(got[2], -1.0);
  EXPECT_EQ(got[7], -1.0);
}

TEST(FaultInjectorTest, SpuriousPointsReplaceSomeBeams) {
  FaultInjector inj(Fault(FaultKind::kSpuriousPoints, 0.0, 1.0, 20), 1);
  geometry::LaserScan scan = ScanStamped(0.0);
  sim::SensorReadings readings;
  readings.scan = &scan;
  docking::Observations obs;
  inj.Apply(0.1, 0.1, &readings, &obs);
  int changed = 0;
  for (double r : readings.scan->ranges) changed += r != 2.0;
  EXPECT_GT(changed, 10);  // 20 draws, a few may hit the same beam
  EXPECT_LE(changed, 20);
  EXPECT_EQ(scan.ranges, ScanStamped(0.0).ranges);  // the sensor's own scan is untouched
}

TEST(FaultInjectorTest, SlippingOdometryOverReportsOnlyWhileSlipping) {
  FaultInjector inj(Fault(FaultKind::kOdometrySlip, 1.0, 0.5, 0.4), 1);
  double reported_x = 0.0;
  for (int k = 0; k <= 150; ++k) {  // 0.02 m per step, 3 m in all
    const double t = 0.02 * k;
    docking::Observations obs;
    obs.T_odom_base = Pose2(0.02 * k, 0.0, 0.0);
    sim::SensorReadings readings;
    inj.Apply(t, t, &readings, &obs);
    reported_x = obs.T_odom_base.x;
  }
  // 25 steps of the 150 slip: 0.5 m true becomes 0.7 m; the rest is reported as driven.
  EXPECT_NEAR(reported_x, 3.0 + 0.4 * 0.5, 0.02 * 0.4 + 1e-9);
}

TEST(FaultInjectorTest, LocalisationJumpOffsetsTheEstimateFromItsTime) {
  FaultSpec f = Fault(FaultKind::kLocalisationJump, 2.0);
  f.offset = Pose2(0.2, -0.1, 0.0);
  FaultInjector inj(f, 1);
  for (double t : {1.0, 3.0}) {
    docking::Observations obs;
    obs.T_map_base_estimate = Pose2(1.0, 1.0, 0.5);
    sim::SensorReadings readings;
    inj.Apply(t, std::nan(""), &readings, &obs);
    EXPECT_NEAR(obs.T_map_base_estimate.x, t < 2.0 ? 1.0 : 1.2, 1e-12);
    EXPECT_NEAR(obs.T_map_base_estimate.y, t < 2.0 ? 1.0 : 0.9, 1e-12);
  }
}

TEST(FaultInjectorTest, BlackoutAndBlindCameraUseTheSensorRig) {
  sim::SensorRigConfig sensors;
  FaultInjector(Fault(FaultKind::kLidarBlackout, 2.0, 0.7), 1).ConfigureSensors(&sensors);
  EXPECT_EQ(sensors.blackout_start_s, 2.0);
  EXPECT_EQ(sensors.blackout_duration_s, 0.7);
  EXPECT_FALSE(sensors.camera_blind);
  FaultInjector(Fault(FaultKind::kCameraBlind), 1).ConfigureSensors(&sensors);
  EXPECT_TRUE(sensors.camera_blind);
}

}  // namespace
}  // namespace shelfdock::eval
