// End-to-end docking in the simulator: the Docker sees only scans, odometry, the localisation
// estimate and camera images; the scores compare against the simulator's ground truth.
#include <cmath>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "eval/docking_runner.hpp"
#include "eval/monte_carlo.hpp"
#include "eval/random_start.hpp"
#include "io/docking_config_yaml.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "io/scenario_yaml.hpp"

namespace shelfdock::eval {
namespace {

using docking::Method;
using docking::OutcomeCode;

const std::string kRoot = SHELFDOCK_SOURCE_DIR;

struct Fixture {
  std::vector<geometry::ShelfModel> models = io::ReadShelfModels(kRoot + "/config/models.yaml");
  sim::Scenario Load(const std::string& relative) const {
    return io::ReadScenario(kRoot + "/" + relative, models);
  }
};

TEST(DockingSim, BothMethodsDockUnderAShelf29cmAnd10DegOffItsPreset) {
  const Fixture f;
  const sim::Scenario s = f.Load("tests/data/docking_offset_shelf.yaml");
  for (Method method : {Method::kContinuous, Method::kStopAndRecognise}) {
    const DockingRun run = RunDocking(s, f.models, method, 3, RunConfig{});
    ASSERT_TRUE(run.outcome.ok()) << run.outcome.reason;
    ASSERT_TRUE(run.error_before_check.valid);
    // The paper's band before the code check, the band after it.
    EXPECT_LT(std::abs(run.error_before_check.x), 0.010);
    EXPECT_LT(std::abs(run.error_before_check.y), 0.010);
    EXPECT_LT(std::abs(run.error_before_check.yaw), 0.014);
    ASSERT_TRUE(run.error_after_check.valid);
    EXPECT_LT(std::abs(run.error_after_check.x), 0.003);
    EXPECT_LT(std::abs(run.error_after_check.y), 0.003);
    EXPECT_LT(std::abs(run.error_after_check.yaw), 0.005);
    EXPECT_GT(run.min_leg_clearance_m, 0.05);  // never near a leg (true geometry)
    EXPECT_GE(run.detections, 1);
  }
}

TEST(DockingSim, TurnsTowardAnEntryNoSmoothCurveReaches) {
  // Seed 1029 of the drift scenario puts the preset (and with it the docking area's entry) so far
  // to the side of the start that no curve within the curvature bound reaches it: the robot turns
  // on the spot first, then approaches and docks.
  const Fixture f;
  const sim::Scenario s = f.Load("config/scenarios/paper_docking_drift.yaml");
  RunConfig config;
  config.record = true;
  const DockingRun run = RunDocking(s, f.models, Method::kContinuous, 1029, config);
  ASSERT_TRUE(run.outcome.ok()) << run.outcome.reason;
  // The approach planner either turns first or takes a shorter docking area it can reach with a
  // smooth curve (a turn costs turn_penalty_m of straight); either way it plans an approach.
  bool planned = false;
  for (const RecordFrame& frame : run.record) {
    for (const std::string& e : frame.events) planned |= e.rfind("approach: ", 0) == 0;
  }
  EXPECT_TRUE(planned);
  ASSERT_TRUE(run.error_after_check.valid);
  EXPECT_LT(std::abs(run.error_after_check.x), 0.003);
  EXPECT_LT(std::abs(run.error_after_check.y), 0.003);
  EXPECT_LT(std::abs(run.error_after_check.yaw), 0.005);
  EXPECT_GT(run.min_leg_clearance_m, 0.05);
}

TEST(DockingSim, EachFailureIsReportedWithItsReason) {
  const Fixture f;
  struct Case {
    const char* scenario;
    OutcomeCode expected;
    double blackout_s = -1.0;      ///< LiDAR blackout from this long after the entry
    bool camera_blind = false;     ///< the camera never sees a code
    const char* config = nullptr;  ///< docking config YAML (tests/data)
  };
  const char* kPaper = "config/scenarios/paper_docking.yaml";
  // too_many_replans needs a goal that moves back and forth, which the simulator's shelves do
  // not do: docker_test.cpp scripts it.
  const Case cases[] = {
      {"tests/data/docking_shelf_absent.yaml", OutcomeCode::kShelfNotFound},
      {"tests/data/docking_wrong_code.yaml", OutcomeCode::kWrongShelf},
      {"tests/data/docking_person_crossing.yaml", OutcomeCode::kWouldCollide},
      {kPaper, OutcomeCode::kDetectionLost, 3.0},
      {kPaper, OutcomeCode::kCodeNotFound, -1.0, true},
      {kPaper, OutcomeCode::kTimeout, -1.0, false, "tests/data/docking_config_tiny_timeout.yaml"},
  };
  for (const Case& c : cases) {
    RunConfig config;
    config.sensors.blackout_start_s = c.blackout_s;
    config.sensors.camera_blind = c.camera_blind;
    if (c.config != nullptr) config.docking = io::ReadDockingConfig(kRoot + "/" + c.config);
    const DockingRun run = RunDocking(f.Load(c.scenario), f.models, Method::kContinuous, 1, config);
    const std::string name = std::string(c.scenario) + " " + (c.config ? c.config : "") +
                             (c.camera_blind ? " camera blind" : "");
    EXPECT_EQ(run.outcome.code, c.expected) << name << ": " << run.outcome.reason;
    EXPECT_FALSE(run.outcome.reason.empty());
    EXPECT_GT(run.min_leg_clearance_m, 0.05) << name;
    EXPECT_FALSE(run.error_after_check.valid) << name << ": no lift after a failure";
    EXPECT_LT(run.time_s, config.docking.timeout_s + 5.0) << name << ": never a hang";
  }
}

// Docks under `target` of the aisle scenario with `seed` and checks the outcome against truth:
// success, after the code check within 2 mm / 5 mrad of the true goal, no leg touched.
void ExpectAisleDocking(const Fixture& f, sim::Scenario s, int target, std::uint64_t seed,
                        const RunConfig& config = {}) {
  s.target_shelf_id = target;
  const DockingRun run = RunDocking(s, f.models, Method::kContinuous, seed, config);
  const std::string name = std::to_string(target) + " seed " + std::to_string(seed);
  ASSERT_TRUE(run.outcome.ok()) << name << ": " << run.outcome.reason;
  EXPECT_LT(std::abs(run.error_after_check.x), 0.002) << name;
  EXPECT_LT(std::abs(run.error_after_check.y), 0.002) << name;
  EXPECT_LT(std::abs(run.error_after_check.yaw), 0.005) << name;
  EXPECT_GT(run.min_leg_clearance_m, 0.0) << name;
}

TEST(DockingSim, AisleTargetsOnBothSidesDockWithAShorterArea) {
  // The paper's 4.5 m docking area does not fit across the 3 m aisle: the Docker shortens it to
  // what the aisle allows and enters after a 90 degree turn, from either side of the aisle.
  const Fixture f;
  const sim::Scenario s = f.Load("config/scenarios/warehouse_aisle.yaml");
  for (int target : {104, 204}) {
    for (std::uint64_t seed : {1u, 2u}) ExpectAisleDocking(f, s, target, seed);
  }
}

TEST(DockingSim, StrayEchoesStopNothing) {
  // A LiDAR whose beams return a stray echo one time in a hundred
  // (config/lidar_variants/stray_echoes.yaml): about 8 false returns a scan, anywhere. Counted as
  // obstacles, some stood on the way in nearly every scan, the approach waited for the way to
  // clear until it gave up, and no run docked (eval-docking, warehouse_aisle, 50 of 50 timed
  // out). A return that neither a neighbouring beam nor the scan before corroborates stops
  // nothing (ObstacleReturns): docked within 2 mm / 5 mrad, no leg touched. Seed 126 without
  // strays: with the neighbouring beam alone a thin leg 2-3 m off, seen by one beam now and
  // then, made the approach blocked and clear by turns until it timed out.
  const Fixture f;
  const sim::Scenario s = f.Load("config/scenarios/warehouse_aisle.yaml");
  RunConfig config;
  config.lidar = io::ReadLidarConfig(kRoot + "/config/lidar_variants/stray_echoes.yaml");
  for (std::uint64_t seed : {1u, 2u}) ExpectAisleDocking(f, s, 104, seed, config);
  RunConfig off = config;
  off.docking.safety.obstacle_neighbour_gap_m = 0.0;
  EXPECT_FALSE(RunDocking(s, f.models, Method::kContinuous, 1, off).outcome.ok());
  ExpectAisleDocking(f, s, 104, 126);
}

TEST(DockingSim, AShelfOffItsDrawingIsDockedUnderByItsCode) {
  // config/scenarios/paper_docking_as_built.yaml: the paper's shelf with each leg 5-10 mm off
  // the model's place and turned by up to 0.04 rad. The LiDAR's pose of it is the legs' best fit
  // to the model, millimetres off the frame's (the near legs weigh most); the code under the
  // shelf names where the frame is, and the robot stops there: within 2 mm / 5 mrad of the true
  // shelf after the check, as for a shelf as designed, no leg touched.
  const Fixture f;
  const sim::Scenario s = f.Load("config/scenarios/paper_docking_as_built.yaml");
  for (std::uint64_t seed : {1u, 2u}) ExpectAisleDocking(f, s, 2, seed);
}

TEST(DockingSim, AisleShelvesFarFromTheirMapPoseAreStillFound) {
  // Seeds whose target drifted far from its map pose (the scenario allows 0.3 m / 0.17 rad):
  // a detector preset gate of 0.4 m / 0.25 rad never returned the shelf on these, and the robot
  // stood before its own guess of the docking area until it gave up (would_collide).
  const Fixture f;
  const sim::Scenario s = f.Load("config/scenarios/warehouse_aisle.yaml");
  for (const auto& [target, seed] :
       {std::pair{104, 17u}, std::pair{104, 65u}, std::pair{204, 10u}, std::pair{204, 53u}}) {
    ExpectAisleDocking(f, s, target, seed);
  }
}

TEST(DockingSim, AShelfAgainstAWallLeavesRoomToDock) {
  // config/scenarios/against_wall.yaml: the target's back legs 5 cm in front of a wall, its map
  // pose up to 0.2 m / 0.1 rad off. On these seeds the preset put the map's wall under the
  // shelf, so neither end seemed to leave room for the robot (no_path), until the map's
  // obstacles within the preset's error of the target were left to the live checks and the
  // detections, as the scan's points there already were. Docked within 2 mm / 5 mrad of the
  // true shelf, no leg touched.
  const Fixture f;
  const sim::Scenario s = f.Load("config/scenarios/against_wall.yaml");
  for (std::uint64_t seed : {19u, 26u, 43u}) ExpectAisleDocking(f, s, 103, seed);
}

TEST(DockingSim, RandomStartsReachTheShelf) {
  // Anywhere 0.3-8 m from the shelf, any heading: a handful of the CLI's sweep.
  const Fixture f;
  const sim::Scenario s = f.Load("config/scenarios/paper_docking.yaml");
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    RunConfig config;
    config.T_map_robot_start =
        RandomStart(s, seed, config.robot.footprint_length_m, config.robot.footprint_width_m);
    ASSERT_TRUE(config.T_map_robot_start);
    const DockingRun run = RunDocking(s, f.models, Method::kContinuous, seed, config);
    EXPECT_TRUE(run.outcome.ok()) << "seed " << seed << ": " << run.outcome.reason;
    EXPECT_GT(run.min_leg_clearance_m, 0.0) << "seed " << seed;
  }
}

TEST(DockingSim, TheBaselineFailsTheSameWayWithoutACode) {
  const Fixture f;
  RunConfig config;
  config.sensors.camera_blind = true;
  const DockingRun run = RunDocking(f.Load("config/scenarios/paper_docking.yaml"), f.models,
                                    Method::kStopAndRecognise, 2, config);
  EXPECT_EQ(run.outcome.code, OutcomeCode::kCodeNotFound) << run.outcome.reason;
  EXPECT_TRUE(run.error_before_check.valid) << "it reached the check";
  EXPECT_FALSE(run.error_after_check.valid);
}

TEST(DockingSim, MonteCarloMeetsThePapersAccuracyAndBeatsTheBaseline) {
  const Fixture f;
  const sim::Scenario s = f.Load("config/scenarios/paper_docking.yaml");
  constexpr int kSeeds = 20;
  std::vector<DockingRun> cont, base;
  for (int seed = 100; seed < 100 + kSeeds; ++seed) {
    cont.push_back(RunDocking(s, f.models, Method::kContinuous, seed, RunConfig{}));
    base.push_back(RunDocking(s, f.models, Method::kStopAndRecognise, seed, RunConfig{}));
  }
  const AccuracyBands bands;
  const MethodSummary c = Summarise(cont, bands);
  const MethodSummary b = Summarise(base, bands);
  EXPECT_EQ(c.successes, kSeeds);
  EXPECT_EQ(b.successes, kSeeds);
  // The paper's result (section 4): before the code check, x and y within 10 mm and yaw within
  // 14 mrad for 95% of the runs; the band after the check for every run.
  EXPECT_LE(c.before_x.p95, bands.before_xy_m);
  EXPECT_LE(c.before_y.p95, bands.before_xy_m);
  EXPECT_LE(c.before_yaw.p95, bands.before_yaw_rad);
  EXPECT_GE(c.within_before, 0.95);
  // Issue 8's band before the check (p99 within 5 mm and 5 mrad, measured over 500 runs by
  // eval-docking: 1.9 mm / 1.7 mm / 4.2 mrad): on these 20 seeds every run of the continuous
  // method is within it.
  for (const DockingRun& r : cont) {
    EXPECT_LE(std::abs(r.error_before_check.x), 0.005) << "seed " << r.seed;
    EXPECT_LE(std::abs(r.error_before_check.y), 0.005) << "seed " << r.seed;
    EXPECT_LE(std::abs(r.error_before_check.yaw), 0.005) << "seed " << r.seed;
  }
  for (const MethodSummary* m : {&c, &b}) {
    EXPECT_LE(m->after_x.max, bands.after_xy_m);
    EXPECT_LE(m->after_y.max, bands.after_xy_m);
    EXPECT_LE(m->after_yaw.max, bands.after_yaw_rad);
    EXPECT_GT(m->min_leg_clearance_m, 0.05);
  }
  // Time on the same seeds, from crossing the docking area's entry (entered at ~0.4 m/s after
  // the approach) to the end of the lift. The issue asks for 25% (the paper: 25.9%, 11.21 s vs
  // 15.14 s); that is NOT met here: both methods use the camera in advance and share the 2 s
  // lift, ~11.9 s of driving and ~0.35 s of code check, so the baseline's only extra cost is the
  // stop at the parking spot (~0.9 s of braking and re-accelerating), standing to recognise
  // (settle_s 1 s + 5 scans = 1.31 s) and its larger blind-docking error (longer adjustments).
  // Measured 18.7 % on seeds 1000-1499 (13.72 s vs 16.88 s: eval-docking --runs 500 --seed0 1000).
  // Asserted with a margin of ~4 points: at least 12% faster on average, and on no seed more
  // than 0.5 s slower (one method may need a fine adjustment where the other does not).
  EXPECT_LE(c.mean_time_s, 0.88 * b.mean_time_s) << c.mean_time_s << " vs " << b.mean_time_s;
  for (int i = 0; i < kSeeds; ++i) {
    EXPECT_LT(cont[i].time_s, base[i].time_s + 0.5) << "seed " << cont[i].seed;
  }
  // No run can beat a robot that knows the true shelf pose and never stops to look (timed on the
  // same definition: from the entry crossing at the docking speed; 13.7 s here).
  const double perfect = PerfectKnowledgeTime(s, RunConfig{});
  // Entering at cruise speed v, it drives d = entry_distance_m at v and brakes at a_dec at the
  // end (costing v / 2 a_dec over cruising), then lifts: a count from the start of the approach
  // would exceed the upper bound by seconds.
  const RunConfig defaults;
  const double d = defaults.docking.entry_distance_m;
  const double v = defaults.docking.controller.max_speed_mps;
  const double a = defaults.docking.controller.max_decel_mps2;
  const double lift = defaults.robot.lift_duration_s;
  EXPECT_GT(perfect, d / v + lift);
  EXPECT_LT(perfect, d / v + v / (2.0 * a) + lift + 0.1);
  for (const DockingRun& r : cont) EXPECT_GT(r.time_s, perfect - 1e-9) << "seed " << r.seed;
  // Issue 8's time target: within 3 % of that bound on average (measured 1.002x over 500 runs).
  EXPECT_LE(c.mean_time_s, 1.03 * perfect) << c.mean_time_s << " vs " << perfect;
}

}  // namespace
}  // namespace shelfdock::eval
