// The Docker driven by a scripted world: a perfect kinematic robot, a detector that reports the
// true shelf (or what the test scripts), and a code under the shelf seen by an ideal camera.
// Every phase transition and every failure, asserted against the scripted ground truth.
#include "docking/docker.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <set>

#include <gtest/gtest.h>

#include "../common/paper_models.hpp"
#include "docking/collision_check.hpp"

namespace shelfdock::docking {
namespace {

using geometry::Pose2;

/// A scripted world around one Docker. Odometry and localisation are perfect, so the docking
/// error is the Docker's own.
struct ScriptedRun {
  DockingConfig config;
  DockingTask task;
  Pose2 T_world_shelf{5.0, 1.0, 0.2};     ///< true shelf (= preset unless the test moves it)
  Pose2 T_world_base{0.0, 1.0, 0.0};      ///< true robot
  Pose2 preset_error{0.05, -0.04, 0.03};  ///< the preset against the true shelf (shelf frame)
  double t_s = 0.0;
  double scan_period_s = 1.0 / 15.0;
  double camera_period_s = 1.0 / 15.0;
  double lift_s = 0.5;
  double max_t_s = 80.0;
  /// What the detector reports for the true shelf in the lidar frame; empty: nothing.
  std::function<std::vector<perception::Detection>(const Pose2& T_lidar_shelf, int scan)> detect =
      [](const Pose2& T_lidar_shelf, int) {
        perception::Detection d;
        d.model = testing::PaperModels()[1].name;
        d.T_lidar_shelf = T_lidar_shelf;
        d.legs_used = 4;
        d.covariance = Eigen::Vector3d(1e-5, 1e-5, 1e-5).asDiagonal();
        return std::vector<perception::Detection>{d};
      };
  int marker_id = 2;     ///< the code under the shelf
  bool scans_on = true;  ///< false: the LiDAR delivers nothing
  bool camera_sees = true;
  Pose2 T_map_world_error;                      ///< localisation error (identity: perfect)
  std::function<void(ScriptedRun*)> each_step;  ///< lets a test push the robot

  std::vector<Phase> phases;  ///< each phase once, in the order entered
  std::vector<std::string> events;
  std::optional<Docker> docker;

  ScriptedRun() {
    task.shelf_id = 2;
    task.model = testing::PaperModels()[1];  // t1-rect-1075x883, the paper's shelf 2
  }

  Outcome Run() {
    task.T_map_shelf_preset = T_world_shelf * preset_error;
    int scans = 0;
    docker.emplace(config, task, Method::kContinuous,
                   [this, &scans](const std::vector<perception::ScanPoint>&, double,
                                  const std::optional<Pose2>&) {
                     perception::DetectionResult r;
                     const Pose2 T_lidar_shelf =
                         (T_world_base * config.T_base_lidar).inverse() * T_world_shelf;
                     r.detections = detect(T_lidar_shelf, scans++);
                     return r;
                   });
    geometry::LaserScan scan;  // one return far behind the robot: the detector is scripted
    scan.angle_min = std::numbers::pi - 0.01;
    scan.angle_increment = 0.01;
    scan.angle_max = scan.angle_min + 2 * scan.angle_increment;
    scan.range_min = 0.05;
    scan.range_max = 30.0;
    scan.ranges = {6.0, 6.0, 6.0};
    double next_scan = 0.0, next_frame = 0.0, lift_at = -1.0;
    bool camera_on = false;
    const double dt = config.control_period_s;
    while (!docker->done() && t_s < max_t_s) {
      Observations obs;
      obs.t_s = t_s;
      obs.T_odom_base = T_world_base;
      obs.T_map_base_estimate = T_map_world_error * T_world_base;
      scan.stamp = t_s - scan_period_s;
      scan.time_increment = 0.0;
      if (scans_on && t_s + 1e-9 >= next_scan) {
        next_scan += scan_period_s;
        obs.scan = &scan;
      }
      if (camera_on && t_s + 1e-9 >= next_frame) {
        next_frame = t_s + camera_period_s;
        obs.camera_frame = true;
        const Pose2 T_base_tag = T_world_base.inverse() * T_world_shelf;
        if (camera_sees && std::abs(T_base_tag.x) < 0.1 && std::abs(T_base_tag.y) < 0.1) {
          obs.marker = perception::MarkerObservation{marker_id, T_base_tag};
        }
      }
      obs.lift_done = lift_at >= 0.0 && t_s >= lift_at;
      const Command cmd = docker->Step(obs);
      if (phases.empty() || phases.back() != docker->phase()) phases.push_back(docker->phase());
      events.insert(events.end(), cmd.events.begin(), cmd.events.end());
      camera_on = cmd.camera_on;
      if (cmd.start_lift) lift_at = t_s + lift_s;
      // A perfect differential drive: the command over one period along an arc.
      const double v = cmd.velocity.v_mps, w = cmd.velocity.w_radps;
      T_world_base =
          T_world_base * Pose2(std::abs(w) < 1e-9 ? v * dt : v / w * std::sin(w * dt),
                               std::abs(w) < 1e-9 ? 0.0 : v / w * (1 - std::cos(w * dt)), w * dt);
      if (each_step) each_step(this);
      t_s += dt;
    }
    return docker->outcome();
  }

  bool Saw(Phase p) const { return std::find(phases.begin(), phases.end(), p) != phases.end(); }
  bool Event(const std::string& prefix) const {
    return std::any_of(events.begin(), events.end(),
                       [&](const std::string& e) { return e.rfind(prefix, 0) == 0; });
  }
  /// The robot against the true goal (the branch of the goal heading it faces).
  Pose2 Error() const {
    const Pose2 T_shelf_base = T_world_shelf.inverse() * T_world_base;
    return GoalBranchNearHeading(Pose2(), T_shelf_base.yaw).inverse() * T_shelf_base;
  }
};

/// Walls as discs 5 cm apart (the map a test gives the Docker).
void AddWall(const Eigen::Vector2d& a, const Eigen::Vector2d& b, FreeSpace* map) {
  const int n = static_cast<int>(std::ceil((b - a).norm() / 0.05));
  for (int i = 0; i <= n; ++i) map->obstacles.push_back({a + (b - a) * (1.0 * i / n), 0.03});
}

constexpr double kAfterXy_m = 0.002;  // the after-check band
constexpr double kAfterYaw_rad = 0.005;

TEST(Docker, OutcomeIsPendingUntilTheDockerSetsIt) {
  const Outcome outcome;
  EXPECT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.code, OutcomeCode::kPending);
  EXPECT_EQ(ToString(outcome.code), "pending");
  ScriptedRun run;
  run.max_t_s = 0.1;  // stops long before the end
  run.Run();
  EXPECT_FALSE(run.docker->outcome().ok());
}

TEST(Docker, OpenSpaceGoesThroughEveryPhaseInOrderAndLandsOnTheTruth) {
  ScriptedRun run;
  const Outcome outcome = run.Run();
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  // The code read on the way in is the check when it puts the stop within tolerance; else a
  // standing check (kVerify) and adjustments (kAdjust) come before the lift.
  const std::vector<Phase> expected{Phase::kApproach, Phase::kDock, Phase::kLift, Phase::kDone};
  std::vector<Phase> seen;
  for (Phase p : run.phases) {
    if (p != Phase::kAdjust && p != Phase::kVerify) seen.push_back(p);
  }
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  EXPECT_EQ(seen, expected);
  ASSERT_TRUE(run.docker->docking_area());
  EXPECT_NEAR(run.docker->docking_area()->entry_distance_m, run.config.entry_distance_m, 1e-6);
  EXPECT_EQ(run.docker->approach_kind(), ApproachKind::kSmooth);
  EXPECT_GE(run.docker->code_checks(), 1);
  const Pose2 e = run.Error();
  EXPECT_LT(std::abs(e.x), kAfterXy_m);
  EXPECT_LT(std::abs(e.y), kAfterXy_m);
  EXPECT_LT(std::abs(e.yaw), kAfterYaw_rad);
}

TEST(Docker, StartFacingAwayTurnsOnTheSpotAndDocks) {
  ScriptedRun run;
  run.T_world_base = Pose2(1.0, 1.0, std::numbers::pi);  // 4 m from the shelf, back to it
  const Outcome outcome = run.Run();
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_TRUE(run.docker->approach_kind() == ApproachKind::kTurnThenSmooth ||
              run.docker->approach_kind() == ApproachKind::kTurnDriveTurn);
  EXPECT_LT(std::abs(run.Error().y), kAfterXy_m);
}

TEST(Docker, StartHalfUnderTheShelfMovesOutAndDocks) {
  ScriptedRun run;
  // Between the legs, 0.35 m from the centre along the long side, facing out of the shelf.
  run.T_world_base = run.T_world_shelf * Pose2(0.35, 0.0, 0.0);
  const Outcome outcome = run.Run();
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_LT(std::abs(run.Error().x), kAfterXy_m);
  EXPECT_LT(std::abs(run.Error().y), kAfterXy_m);
}

TEST(Docker, AnAisleShortensTheDockingAreaToWhatFits) {
  ScriptedRun run;
  // The shelf's long side across a 3 m aisle: its entry faces the aisle, whose far side (a rack
  // front) stands 3 m + half the shelf from its centre.
  run.T_world_shelf = Pose2(5.0, 2.1, 0.5 * std::numbers::pi);
  run.preset_error = Pose2();  // the area is measured from the preset
  run.T_world_base = Pose2(0.0, 0.0, 0.0);
  AddWall({-1.0, -1.56}, {10.0, -1.56}, &run.task.map_obstacles);  // the opposite row's legs
  AddWall({-1.0, 3.0}, {10.0, 3.0}, &run.task.map_obstacles);      // rack behind the shelf
  const Outcome outcome = run.Run();
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  ASSERT_TRUE(run.docker->docking_area());
  const double straight = run.docker->docking_area()->entry_distance_m;
  // The footprint (0.62 long by default) must stay obstacle_margin_m from the far wall.
  const double fits = 2.1 + 1.56 - 0.5 * run.config.safety.robot_length_m -
                      run.config.safety.obstacle_margin_m - 0.03;
  EXPECT_LT(straight, fits + 0.001);
  EXPECT_GT(straight, fits - 0.06);  // within one search step
  EXPECT_LT(std::abs(run.Error().y), kAfterXy_m);
}

TEST(Docker, BothEndsWalledInIsNoPath) {
  ScriptedRun run;
  AddWall({4.0, -3.0}, {4.0, 5.0}, &run.task.map_obstacles);  // 1 m behind each end
  AddWall({6.0, -3.0}, {6.0, 5.0}, &run.task.map_obstacles);
  run.T_world_shelf = Pose2(5.0, 1.0, 0.0);
  run.T_world_base = Pose2(2.0, 1.0, 0.0);
  EXPECT_EQ(run.Run().code, OutcomeCode::kNoPath) << run.docker->outcome().reason;
}

TEST(Docker, NoDetectionIsShelfNotFound) {
  ScriptedRun run;
  run.detect = [](const Pose2&, int) { return std::vector<perception::Detection>{}; };
  EXPECT_EQ(run.Run().code, OutcomeCode::kShelfNotFound) << run.docker->outcome().reason;
  EXPECT_TRUE(run.Saw(Phase::kAbort));
}

TEST(Docker, NoScansIsDetectionLost) {
  ScriptedRun run;
  run.scans_on = false;
  EXPECT_EQ(run.Run().code, OutcomeCode::kDetectionLost) << run.docker->outcome().reason;
}

// Issue 10 (eval faults): a LiDAR silent for 1.5 s used to abort at once (detection_lost after
// scan_timeout_s = 0.5 s); now the robot stops until the scans return, then docks.
TEST(Docker, ALidarSilentForAWhileStopsTheRobotAndDocksWhenScansReturn) {
  ScriptedRun run;
  double entered = -1.0;
  std::optional<Pose2> stopped_at;
  double moved_while_stopped_m = 0.0;
  run.each_step = [&](ScriptedRun* r) {
    if (entered < 0.0 && r->docker->phase() == Phase::kDock) entered = r->t_s;
    const double since = entered < 0.0 ? -1.0 : r->t_s - entered;
    r->scans_on = !(since >= 1.0 && since < 2.5);
    // Braking from 0.4 m/s at 1.5 x 0.4 m/s^2 takes 0.67 s after the 0.5 s timeout: standing by
    // 2.3 s, still before the scans return.
    if (since >= 2.3 && since < 2.45) {
      if (!stopped_at) stopped_at = r->T_world_base;
      moved_while_stopped_m =
          std::max(moved_while_stopped_m, geometry::Distance(*stopped_at, r->T_world_base));
    }
  };
  const Outcome outcome = run.Run();
  EXPECT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_TRUE(run.Event("lidar_silent"));
  EXPECT_TRUE(run.Event("lidar_back"));
  ASSERT_TRUE(stopped_at.has_value());
  EXPECT_LT(moved_while_stopped_m, 1e-6);
}

// Issue 10 (eval faults): the localisation estimate jumping 0.3 m sideways during the approach
// put the robot "off the approach path" (max_cross_track_m 0.25 m) and ended the attempt as
// tracking_failed; now it stops, plans the approach again from the new estimate and docks.
TEST(Docker, ALocalisationJumpOnTheApproachIsReplannedAndDocks) {
  ScriptedRun run;
  run.T_world_base = Pose2(-2.5, 1.0, 0.0);  // 3 m of approach before the docking area
  // The approach curves toward the entry, and a sideways jump partly projects along it: a
  // tighter bound than the default 0.25 m makes the 0.3 m jump leave the path for sure.
  run.config.controller.max_cross_track_m = 0.15;
  run.each_step = [](ScriptedRun* r) {
    if (r->docker->phase() == Phase::kApproach && r->T_world_base.x > -2.3) {
      r->T_map_world_error = Pose2(0.0, 0.3, 0.0);
    }
  };
  const Outcome outcome = run.Run();
  EXPECT_TRUE(outcome.ok()) << outcome.reason;
  std::string events;
  for (const auto& e : run.events) events += e + "\n";
  EXPECT_TRUE(run.Event("approach_off_path")) << events;
}

TEST(Docker, AnotherCodeIsWrongShelf) {
  ScriptedRun run;
  run.marker_id = 9;
  EXPECT_EQ(run.Run().code, OutcomeCode::kWrongShelf) << run.docker->outcome().reason;
  EXPECT_TRUE(run.Saw(Phase::kVerify));
}

TEST(Docker, NoCodeIsCodeNotFound) {
  ScriptedRun run;
  run.camera_sees = false;
  EXPECT_EQ(run.Run().code, OutcomeCode::kCodeNotFound) << run.docker->outcome().reason;
}

TEST(Docker, TinyBudgetIsTimeout) {
  ScriptedRun run;
  run.config.timeout_s = 2.0;
  EXPECT_EQ(run.Run().code, OutcomeCode::kTimeout) << run.docker->outcome().reason;
}

TEST(Docker, AGoalThatOscillatesIsTooManyReplans) {
  ScriptedRun run;
  run.config.max_replans = 3;
  run.config.tracker.gate_xy_m = 1.0;
  // A tracker that follows each detection (tiny floor, large drift), so the goal moves with it.
  run.config.tracker.min_sigma_xy_m = 1e-4;
  run.config.tracker.drift_sigma_xy_per_m = 10.0;
  auto base = run.detect;
  run.detect = [base](const Pose2& T, int scan) {
    // 3 cm to either side on alternate scans: no net movement of the goal.
    return base(T * Pose2(0.0, scan % 2 == 0 ? 0.03 : -0.03, 0.0), scan);
  };
  EXPECT_EQ(run.Run().code, OutcomeCode::kTooManyReplans) << run.docker->outcome().reason;
}

TEST(Docker, ANeighbourShelfInViewDoesNotMoveTheGoal) {
  ScriptedRun run;
  auto base = run.detect;
  run.detect = [base](const Pose2& T, int scan) {
    // The neighbour 1.4 m to the side is reported first, every scan.
    std::vector<perception::Detection> out = base(T * Pose2(0.0, 1.4, 0.0), scan);
    const auto mine = base(T, scan);
    out.insert(out.end(), mine.begin(), mine.end());
    return out;
  };
  const Outcome outcome = run.Run();
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_LE(run.docker->replans(), 2);
  EXPECT_LT(std::abs(run.Error().y), kAfterXy_m);
}

TEST(Docker, AGoalThatMovesCloseInBendsThePathAndTheRobotStopsOnIt) {
  // Detections 4 mm / 4 mrad off until the base is about 0.45 m from the goal, exact after
  // (the far legs alone, close in): the goal moves when little straight is left. The path is
  // bent onto it each time (no re-plan from the robot's pose fails or kicks the controller) and
  // the LiDAR alone, without the camera's guidance, stops the robot within the code check's
  // tolerance: no adjustment.
  ScriptedRun run;
  run.config.camera_guide.enabled = false;
  auto base = run.detect;
  run.detect = [base](const Pose2& T, int scan) {
    const bool far = T.translation().norm() > 0.75;
    return base(far ? T * Pose2(0.0, 0.004, 0.004) : T, scan);
  };
  const Outcome outcome = run.Run();
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  EXPECT_TRUE(run.Event("plan_bent"));
  EXPECT_FALSE(run.Event("plan_failed"));
  EXPECT_FALSE(run.Event("adjust"));
  const Pose2 e = run.Error();
  EXPECT_LT(std::abs(e.x), run.config.verify.tolerance_xy_m);
  EXPECT_LT(std::abs(e.y), run.config.verify.tolerance_xy_m);
  EXPECT_LT(std::abs(e.yaw), run.config.verify.tolerance_yaw_rad);
}

TEST(Docker, APushOffThePathIsATrackingFailure) {
  ScriptedRun run;
  run.each_step = [](ScriptedRun* r) {
    // Half a metre sideways once the robot is docking (a collision, a slipping wheel).
    if (r->docker->phase() == Phase::kDock && r->T_world_base.x > 2.0 && r->T_world_base.x < 2.1) {
      r->T_world_base = r->T_world_base * Pose2(0.0, 0.5, 0.0);
    }
  };
  EXPECT_EQ(run.Run().code, OutcomeCode::kTrackingFailed) << run.docker->outcome().reason;
}

TEST(Docker, TypedOutcomesHaveDistinctNames) {
  std::set<std::string_view> names;
  for (OutcomeCode c :
       {OutcomeCode::kPending, OutcomeCode::kSuccess, OutcomeCode::kShelfNotFound,
        OutcomeCode::kDetectionLost, OutcomeCode::kWouldCollide, OutcomeCode::kNoPath,
        OutcomeCode::kTrackingFailed, OutcomeCode::kWrongShelf, OutcomeCode::kCodeNotFound,
        OutcomeCode::kTimeout, OutcomeCode::kTooManyReplans}) {
    EXPECT_TRUE(names.insert(ToString(c)).second) << ToString(c);
  }
}

}  // namespace
}  // namespace shelfdock::docking
