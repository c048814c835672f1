#include "eval/docking_runner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "docking/docking_area.hpp"
#include "docking/path_planner.hpp"
#include "docking/path_tracker.hpp"
#include "eval/fault_injector.hpp"
#include "eval/known_map.hpp"
#include "geometry/angle.hpp"
#include "perception/detector.hpp"
#include "sim/world.hpp"

namespace shelfdock::eval {
namespace {

using geometry::Pose2;

double BoxDistance(const Eigen::Vector2d& p, double half_x, double half_y) {
  const Eigen::Vector2d d(std::abs(p.x()) - half_x, std::abs(p.y()) - half_y);
  return d.cwiseMax(0.0).norm() + std::min(std::max(d.x(), d.y()), 0.0);
}

const geometry::ShelfModel* FindModel(const std::vector<geometry::ShelfModel>& models,
                                      const std::string& name) {
  for (const auto& m : models) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

/// Error of the robot against the true shelf centre in the goal frame (which end it entered
/// from is the branch of yaw_offset or yaw_offset + pi nearest the robot's heading).
PoseError ErrorInShelfFrame(const Pose2& T_world_base, const Pose2& T_world_shelf,
                            double yaw_offset_rad) {
  const Pose2 T_shelf_base = T_world_shelf.inverse() * T_world_base;
  const Pose2 T_shelf_goal =
      docking::GoalBranchNearHeading(Pose2(0.0, 0.0, yaw_offset_rad), T_shelf_base.yaw);
  const Pose2 e = T_shelf_goal.inverse() * T_shelf_base;
  return {e.x, e.y, e.yaw, true};
}

/// Books one control step (the command it applies) to the phase the Docker is in after it.
void AddPhaseTime(docking::Phase phase, const docking::Command& cmd, double dt_s,
                  PhaseTimes* times) {
  using docking::Phase;
  switch (phase) {
    case Phase::kApproach:
      times->approach_s += dt_s;
      break;
    case Phase::kDock:
      times->dock_s += dt_s;
      if (std::abs(cmd.velocity.v_mps) < 0.1) times->final_slow_s += dt_s;
      break;
    case Phase::kStand:
      times->stand_s += dt_s;
      break;
    case Phase::kVerify:
      times->verify_s += dt_s;
      break;
    case Phase::kAdjust:
      times->adjust_s += dt_s;
      break;
    case Phase::kLift:
      times->lift_s += dt_s;
      break;
    case Phase::kAbort:
      times->abort_s += dt_s;
      break;
    case Phase::kDone:
      break;
  }
}

}  // namespace

double FootprintLegDistance(const Pose2& T_world_base, double length_m, double width_m,
                            const sim::LegFootprint& leg) {
  // Two convex boxes that do not overlap are closest at a vertex of one of them.
  double d = std::numeric_limits<double>::infinity();
  const Pose2 T_base_world = T_world_base.inverse();
  for (const Eigen::Vector2d& c : leg.Corners()) {
    d = std::min(d, BoxDistance(T_base_world * c, 0.5 * length_m, 0.5 * width_m));
  }
  const Pose2 T_leg_world = leg.T_world_leg.inverse();
  for (double sx : {-0.5, 0.5}) {
    for (double sy : {-0.5, 0.5}) {
      const Eigen::Vector2d corner = T_world_base * Eigen::Vector2d(sx * length_m, sy * width_m);
      d = std::min(d, BoxDistance(T_leg_world * corner, 0.5 * leg.length_m, 0.5 * leg.width_m));
    }
  }
  return d;
}

DockingRun RunDocking(const sim::Scenario& scenario,
                      const std::vector<geometry::ShelfModel>& models, docking::Method method,
                      std::uint64_t seed, const RunConfig& config) {
  DockingRun run;
  run.method = method;
  run.seed = seed;

  // What the robot is told.
  docking::DockingTask task;
  task.shelf_id = scenario.target_shelf_id;
  const sim::ScenarioShelf* target = scenario.FindShelf(scenario.target_shelf_id);
  task.T_map_shelf_preset = scenario.PresetPose(scenario.target_shelf_id, seed).value_or(Pose2());
  if (target != nullptr) {
    if (const geometry::ShelfModel* m = FindModel(models, target->model_name)) task.model = *m;
  }
  task.map_obstacles = KnownObstacles(scenario, models, seed);
  const std::optional<sim::ShelfInstance> true_shelf =
      scenario.world.Shelf(scenario.target_shelf_id);

  docking::DockingConfig dcfg = config.docking;
  dcfg.safety.robot_length_m = config.robot.footprint_length_m;
  dcfg.safety.robot_width_m = config.robot.footprint_width_m;
  dcfg.control_period_s = 1.0 / config.robot.control_rate_hz;

  const perception::Detector detector(models, config.detector);
  docking::Docker docker(dcfg, task, method,
                         [&detector](const std::vector<perception::ScanPoint>& points,
                                     double increment, const std::optional<Pose2>& preset) {
                           return detector.DetectPoints(points, increment, preset);
                         });
  perception::MarkerDetector marker_detector(config.marker);

  sim::DiffDriveRobot robot(config.robot,
                            config.T_map_robot_start.value_or(scenario.T_map_robot_start), seed);
  const Pose2 T_base_lidar = dcfg.T_base_lidar;
  const double dt = dcfg.control_period_s;
  FaultInjector faults(config.fault, seed);
  sim::SensorRigConfig sensor_config = config.sensors;
  faults.ConfigureSensors(&sensor_config);
  sim::SensorRig sensors(config.lidar, config.camera, sensor_config, T_base_lidar, seed,
                         robot.time_s());
  int last_path_version = 0;
  bool verify_seen = false;
  bool before_check_set = false;
  bool camera_on = false;  // as the Docker commanded in the last step
  const std::vector<sim::LegFootprint> legs = scenario.world.LegFootprints();

  double true_entry_t = std::numeric_limits<double>::quiet_NaN();
  while (!docker.done() && robot.time_s() < config.max_sim_time_s) {
    const double t = robot.time_s();
    if (std::isnan(true_entry_t) && true_shelf && docker.docking_area()) {
      const docking::DockingArea& area = *docker.docking_area();
      const Pose2 in_goal =
          (true_shelf->T_world_shelf * area.T_shelf_goal).inverse() * robot.T_world_base();
      if (in_goal.x >= -area.entry_distance_m && std::abs(in_goal.y) <= dcfg.area_half_width_m) {
        true_entry_t = t;
      }
    }
    docking::Observations obs;
    obs.t_s = t;
    obs.T_odom_base = robot.T_odom_base();
    obs.T_map_base_estimate = robot.T_map_base_estimate();
    obs.lift_done = robot.LiftDone();
    sim::SensorReadings readings =
        sensors.Sense(scenario.world, robot, t, t - docker.docking_start_time(),
                      camera_on || docker.phase() == docking::Phase::kVerify);
    faults.Apply(t, t - docker.docking_start_time(), &readings, &obs);
    obs.scan = readings.scan;
    obs.camera_frame = readings.camera_frame;
    if (readings.image) obs.marker = marker_detector.Detect(*readings.image, config.camera.camera);
    const bool have_scan = readings.scan != nullptr;

    const docking::Phase phase_before = docker.phase();
    const int detections_before = docker.detections();
    const docking::Command cmd = docker.Step(obs);
    if (config.keep_recognitions && docker.detections() != detections_before &&
        docker.last_detection_odom() && std::isfinite(docker.docking_start_time())) {
      const Pose2 T_world_odom = robot.T_world_base() * obs.T_odom_base.inverse();
      const Pose2 T_map_odom = obs.T_map_base_estimate * obs.T_odom_base.inverse();
      const Pose2& detected = *docker.last_detection_odom();
      const Pose2& fused = docker.shelf_tracker().estimate();
      run.recognitions.push_back({t, T_world_odom * detected, T_world_odom * fused,
                                  T_map_odom * detected, T_map_odom * fused});
    }
    AddPhaseTime(docker.done() ? phase_before : docker.phase(), cmd, dt, &run.phases);

    camera_on = cmd.camera_on;
    // error_before_check is the LiDAR-guided final error (the "before the code check").
    // When the camera corrected the goal on the way in, that is where the LiDAR-guided goal lay
    // in truth at the takeover (the true T_world_odom of that instant maps it); otherwise the
    // robot's pose when it stopped for the check.
    if (!before_check_set && docker.lidar_goal_before_camera() && true_shelf) {
      before_check_set = true;
      const Pose2 T_world_odom = robot.T_world_base() * obs.T_odom_base.inverse();
      run.error_before_check =
          ErrorInShelfFrame(T_world_odom * *docker.lidar_goal_before_camera(),
                            true_shelf->T_world_shelf, dcfg.dock_yaw_offset_rad);
    }
    const bool stopped_for_check =
        docker.phase() == docking::Phase::kVerify || docker.phase() == docking::Phase::kAdjust;
    if (!verify_seen && stopped_for_check && true_shelf) {
      verify_seen = true;
      if (!before_check_set) {
        before_check_set = true;
        run.error_before_check = ErrorInShelfFrame(robot.T_world_base(), true_shelf->T_world_shelf,
                                                   dcfg.dock_yaw_offset_rad);
      }
    }
    if (cmd.start_lift) {
      robot.StartLift();
      if (true_shelf) {
        run.error_after_check = ErrorInShelfFrame(robot.T_world_base(), true_shelf->T_world_shelf,
                                                  dcfg.dock_yaw_offset_rad);
        // Checked on the way in and lifted at once: the stop is the LiDAR-guided pose.
        if (!before_check_set) {
          before_check_set = true;
          run.error_before_check = run.error_after_check;
        }
      }
    }
    for (const sim::LegFootprint& leg : legs) {
      run.min_leg_clearance_m =
          std::min(run.min_leg_clearance_m,
                   FootprintLegDistance(robot.T_world_base(), config.robot.footprint_length_m,
                                        config.robot.footprint_width_m, leg));
    }
    if (config.record) {
      RecordFrame f;
      f.t_s = t;
      f.phase = std::string(docking::ToString(docker.phase()));
      f.T_world_base_true = robot.T_world_base();
      f.T_odom_base = obs.T_odom_base;
      f.T_map_base_estimate = obs.T_map_base_estimate;
      f.v_cmd = cmd.velocity.v_mps;
      f.w_cmd = cmd.velocity.w_radps;
      const Pose2 T_world_odom = robot.T_world_base() * obs.T_odom_base.inverse();
      if (have_scan) {
        const Pose2 T_world_lidar = robot.T_world_base() * T_base_lidar;
        const geometry::LaserScan& scan = *readings.scan;
        for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
          if (!scan.HasReturn(i)) continue;
          const double r = scan.ranges[i];
          const double a = scan.BeamAngle(i);
          f.scan_world.push_back(T_world_lidar * Eigen::Vector2d(r * std::cos(a), r * std::sin(a)));
        }
      }
      if (docker.last_detection_odom())
        f.detection_world = T_world_odom * *docker.last_detection_odom();
      if (docker.shelf_tracker().has_detection()) {
        f.shelf_estimate_world = T_world_odom * docker.shelf_tracker().estimate();
      }
      if (docker.path_version() != last_path_version) {
        const Pose2 T_world_frame = docker.path_in_odom()
                                        ? T_world_odom
                                        : robot.T_world_base() * obs.T_map_base_estimate.inverse();
        for (const auto& p : docker.path().points) f.path_world.push_back(T_world_frame * p.pose);
      }
      f.events = cmd.events;
      run.record.push_back(std::move(f));
    }
    last_path_version = docker.path_version();
    robot.Step(cmd.velocity.v_mps, cmd.velocity.w_radps, dt);
  }

  run.hung = !docker.done();
  run.outcome = docker.done() ? docker.outcome()
                              : docking::Outcome{docking::OutcomeCode::kTimeout,
                                                 "the simulation ran out of time"};
  const double start = std::isfinite(true_entry_t)                  ? true_entry_t
                       : std::isfinite(docker.docking_start_time()) ? docker.docking_start_time()
                                                                    : 0.0;
  run.time_s = robot.time_s() - start;
  run.replans = docker.replans();
  run.detections = docker.detections();
  run.phases.code_checks = docker.code_checks();
  run.phases.adjustments = docker.adjustments();
  return run;
}

double PerfectKnowledgeTime(const sim::Scenario& scenario, const RunConfig& config) {
  const std::optional<sim::ShelfInstance> shelf = scenario.world.Shelf(scenario.target_shelf_id);
  if (!shelf) return std::numeric_limits<double>::quiet_NaN();
  sim::DiffDriveConfig robot_cfg = config.robot;
  robot_cfg.odometry = {};
  sim::DiffDriveRobot robot(robot_cfg, scenario.T_map_robot_start, 0);
  const Pose2 goal =
      shelf->T_world_shelf * docking::NearerEndGoal(shelf->T_world_shelf,
                                                    config.docking.dock_yaw_offset_rad,
                                                    robot.T_world_base());
  const docking::ControllerConfig& ctl = config.docking.controller;
  const double dt = 1.0 / robot_cfg.control_rate_hz;
  docking::PathTracker tracker(ctl);
  // Same definition as DockingRun::time_s: the clock starts when the robot crosses the docking
  // area's entry (entry_distance_m before the goal), which it reaches at the docking speed after
  // the same approach as the Docker's (approach speed, arriving at max_speed_mps).
  const double along = (goal.inverse() * robot.T_world_base()).x;
  double t_entry = 0.0;
  if (along < -(config.docking.entry_distance_m + config.docking.entry_tolerance_m)) {
    const Pose2 entry = goal * Pose2(-config.docking.entry_distance_m, 0.0, 0.0);
    const docking::PlanResult approach =
        docking::PlanDockingPath(robot.T_world_base(), entry, config.docking.planner);
    if (!approach.ok) return std::numeric_limits<double>::quiet_NaN();
    tracker.SetPath(approach.path, ctl.approach_speed_mps, ctl.max_speed_mps, 0.0);
    while (robot.time_s() < config.max_sim_time_s) {
      const docking::TrackingStatus s = tracker.Update(robot.T_world_base(), dt);
      if (s.reached) break;
      robot.Step(s.command.v_mps, s.command.w_radps, dt);
    }
    t_entry = robot.time_s();
  }
  const docking::PlanResult plan =
      docking::PlanDockingPath(robot.T_world_base(), goal, config.docking.planner);
  if (!plan.ok) return std::numeric_limits<double>::quiet_NaN();
  tracker.SetPath(plan.path, ctl.max_speed_mps, 0.0, robot.v());
  while (robot.time_s() < config.max_sim_time_s) {
    const docking::TrackingStatus s = tracker.Update(robot.T_world_base(), dt);
    if (s.reached) break;
    robot.Step(s.command.v_mps, s.command.w_radps, dt);
  }
  return robot.time_s() - t_entry + robot_cfg.lift_duration_s;
}

}  // namespace shelfdock::eval
