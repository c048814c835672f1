// The approach stage: choose the docking area from the free space (which end of the shelf, how
// long a straight), then reach its entry from wherever the robot stands: a smooth curve, turns on
// the spot and straight moves, or first a straight move out (reversing) to where it can turn.
#include <cmath>

#include "docking/collision_check.hpp"
#include "docking/docker.hpp"
#include "docking/path_planner.hpp"

#include "docking/docker_detail.hpp"

namespace shelfdock::docking {

using detail::Fmt;
using geometry::Pose2;

void Docker::Start(const Observations& obs, Command* /*cmd*/) {
  started_ = true;
  t_start_ = obs.t_s;
  last_t_ = obs.t_s - config_.control_period_s;
  last_T_odom_base_ = obs.T_odom_base;
}

namespace {

// The box the target may stand in: its footprint around the preset, grown by the preset's
// error (a sigma off, and turned by a yaw sigma about its centre) and the legs' exclusion.
struct TargetBox {
  TargetBox(const DockingTask& task, const DockingConfig& config)
      : T_shelf_map(task.T_map_shelf_preset.inverse()) {
    const double keep_out =
        config.tracker.preset_sigma_xy_m + config.safety.leg_exclusion_m +
        0.5 * task.model.length_m * std::sin(config.tracker.preset_sigma_yaw_rad);
    half_x = 0.5 * task.model.length_m + keep_out;
    half_y = 0.5 * task.model.width_m + keep_out;
  }
  bool Contains(const Eigen::Vector2d& p_map) const {
    const Eigen::Vector2d p = T_shelf_map * p_map;
    return std::abs(p.x()) < half_x && std::abs(p.y()) < half_y;
  }
  Pose2 T_shelf_map;
  double half_x = 0.0;
  double half_y = 0.0;
};

/// The map's obstacles but those near the target: they stand where the map says, but the target
/// only within its preset's error of where the map says, so a wall just behind a shelf pushed
/// against it (5 cm) would seem to stand under a preset 0.2 m off, and neither end of the shelf
/// would leave room for the robot (config/scenarios/against_wall.yaml, 50 runs: 3 such
/// failures). The docking stage's live checks and the detections place the shelf and what
/// stands around it.
FreeSpace MapAwayFromTarget(const DockingTask& task, const TargetBox& box) {
  FreeSpace space;
  for (const LegDisc& disc : task.map_obstacles.obstacles) {
    if (!box.Contains(disc.centre)) space.obstacles.push_back(disc);
  }
  return space;
}

/// MapAwayFromTarget and what the scan sees (walls and neighbours where they really stand; the
/// map is only as good as its presets), again except near the target, whose legs are placed
/// from the preset and later from detections.
FreeSpace ApproachFreeSpace(const DockingTask& task, const DockingConfig& config,
                            const Observations& obs, const std::vector<char>& obstacle) {
  const TargetBox box(task, config);
  FreeSpace space = MapAwayFromTarget(task, box);
  if (obs.scan == nullptr) return space;
  constexpr double kPointRadius_m = 0.02;
  const Pose2 T_map_lidar = obs.T_map_base_estimate * config.T_base_lidar;
  const geometry::LaserScan& scan = *obs.scan;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (i >= obstacle.size() || !obstacle[i]) continue;
    const double r = scan.ranges[i];
    const double a = scan.BeamAngle(i);
    const Eigen::Vector2d p_map = T_map_lidar * Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
    if (box.Contains(p_map)) continue;
    space.obstacles.push_back({p_map, kPointRadius_m});
  }
  return space;
}

}  // namespace

void Docker::PlanApproachFrom(const Observations& obs, Command* cmd) {
  // Plan on a fresh scan (one scan period at most), so neighbours are where they really stand.
  if (obs.scan == nullptr && obs.t_s - t_start_ < config_.scan_timeout_s) return;
  approach_.free_space = ApproachFreeSpace(task_, config_, obs, obstacle_returns_);
  if (!approach_.area) {
    const DockingAreaResult area = ChooseDockingArea(
        task_.T_map_shelf_preset, obs.T_map_base_estimate, approach_.free_space, config_);
    if (!area.area) {
      Fail(OutcomeCode::kNoPath, area.reason, cmd);
      return;
    }
    approach_.area = area.area;
    T_shelf_goal_ = area.area->T_shelf_goal;
    cmd->events.push_back("docking_area: " + Fmt(area.area->entry_distance_m, 2) +
                          " m straight, goal heading " + Fmt(area.area->T_shelf_goal.yaw, 3) +
                          " rad in the shelf frame");
  }
  for (const LegDisc& leg : LegDiscs(task_.model, task_.T_map_shelf_preset)) {
    approach_.free_space.obstacles.push_back(leg);
  }
  if (++approach_.plans > config_.max_approach_plans) {
    Fail(OutcomeCode::kNoPath,
         "no approach after " + std::to_string(config_.max_approach_plans) + " plans", cmd);
    return;
  }
  const Pose2 T_map_goal = task_.T_map_shelf_preset * T_shelf_goal_;
  approach_.plan = PlanApproach(obs.T_map_base_estimate, T_map_goal,
                                approach_.area->entry_distance_m, approach_.free_space, config_);
  if (!approach_.plan.ok) {
    // What the scan shows may be passing (a person): plan on the map alone, and let the live
    // checks (the approach's re-planning, the docking stage's obstacle stop) deal with it.
    FreeSpace map_only = MapAwayFromTarget(task_, TargetBox(task_, config_));
    for (const LegDisc& leg : LegDiscs(task_.model, task_.T_map_shelf_preset)) {
      map_only.obstacles.push_back(leg);
    }
    ApproachPlan on_map = PlanApproach(obs.T_map_base_estimate, T_map_goal,
                                       approach_.area->entry_distance_m, map_only, config_);
    if (on_map.ok) {
      cmd->events.push_back("approach: planned on the map alone (" + approach_.plan.reason + ")");
      approach_.plan = std::move(on_map);
    }
  }
  const ApproachPlan& plan = approach_.plan;
  if (!plan.ok) {
    Fail(OutcomeCode::kNoPath, plan.reason, cmd);
    return;
  }
  approach_.T_odom_map = obs.T_odom_base * obs.T_map_base_estimate.inverse();
  cmd->events.push_back("approach: " + std::string(ToString(plan.kind)) + ", docking area " +
                        Fmt(plan.entry_distance_m, 2) + " m");
  switch (plan.kind) {
    case ApproachKind::kDockNow:
      StartDocking(obs, cmd);
      if (phase_ == Phase::kDock) StepDock(obs, cmd);
      return;
    case ApproachKind::kSmooth:
      follower_.SetPath(plan.path, config_.controller.approach_speed_mps,
                        config_.controller.max_speed_mps, last_v_cmd_,
                        config_.controller.approach_lateral_settle_m);
      ++path_version_;
      approach_.step = ApproachState::Step::kFollow;
      return;
    case ApproachKind::kTurnThenSmooth:
    case ApproachKind::kTurnDriveTurn:
      manoeuvre_.StartTurn((approach_.T_odom_map * Pose2(0.0, 0.0, plan.first_turn_yaw_rad)).yaw);
      approach_.step = ApproachState::Step::kFirstTurn;
      return;
    case ApproachKind::kMoveOut:
      if (!plan.path.empty()) {  // an arc away from a wall alongside
        follower_.SetPath(plan.path, config_.controller.max_speed_mps, 0.0, 0.0,
                          config_.controller.approach_lateral_settle_m);
        ++path_version_;
      } else {
        manoeuvre_.StartStraight(obs.T_odom_base, approach_.T_odom_map * plan.T_frame_move_to);
      }
      approach_.step = ApproachState::Step::kMoveOut;
      return;
  }
}

bool Docker::ApproachStillClear(const Observations& obs) const {
  // Each scan shows the obstacles near the way where they really stand (the map's presets may be
  // a few decimetres off): the rest of the path, and the turn at the entry, must keep clear.
  FreeSpace space = ApproachFreeSpace(task_, config_, obs, obstacle_returns_);
  const double margin = config_.safety.obstacle_margin_m;
  const ApproachPlan& plan = approach_.plan;
  if (approach_.step == ApproachState::Step::kFollow) {
    const double s_now = follower_.path().Project(obs.T_map_base_estimate).s;
    if (space.PathClearance(follower_.path(), config_.safety, 0.05, s_now) < margin) return false;
  }
  if (plan.kind == ApproachKind::kTurnDriveTurn &&
      space.TurnClearance(plan.T_frame_entry, config_.safety) < margin) {
    return false;
  }
  return true;
}

void Docker::StepApproach(const Observations& obs, double dt, Command* cmd) {
  using Step = ApproachState::Step;
  const ApproachPlan& plan = approach_.plan;
  bool finished = false;
  if (obs.scan != nullptr &&
      (approach_.step == Step::kFollow || approach_.step == Step::kFirstTurn)) {
    const bool clear = ApproachStillClear(obs);
    if (!clear && approach_.replans_for_block < config_.max_block_replans) {
      // Most likely a neighbour standing off its map pose, seen better as the robot nears it:
      // plan again with what the scan shows.
      cmd->events.push_back("approach_blocked: the scan shows an obstacle on the way; re-planning");
      ++approach_.replans_for_block;
      approach_.step = Step::kPlan;
    } else if (!clear && approach_.blocked_since_t < 0.0) {
      cmd->events.push_back("approach_blocked: waiting for the way to clear");
      approach_.blocked_since_t = obs.t_s;
    } else if (clear && approach_.blocked_since_t >= 0.0) {
      cmd->events.push_back("approach_clear");
      approach_.blocked_since_t = -1.0;
      if (approach_.step == Step::kFollow) {
        follower_.SetPath(
            follower_.path(), config_.controller.approach_speed_mps,
            plan.kind == ApproachKind::kTurnDriveTurn ? 0.0 : config_.controller.max_speed_mps,
            last_v_cmd_, config_.controller.approach_lateral_settle_m);
      }
    }
  }
  if (approach_.blocked_since_t >= 0.0 && approach_.step != Step::kPlan) {
    if (obs.t_s - approach_.blocked_since_t > config_.safety.obstacle_wait_s) {
      Fail(OutcomeCode::kWouldCollide,
           "an obstacle blocked the approach for " + Fmt(obs.t_s - approach_.blocked_since_t, 1) +
               " s",
           cmd);
      return;
    }
    cmd->velocity = BrakeCommand(dt);
    return;
  }
  switch (approach_.step) {
    case Step::kPlan:
      // Plan from a standstill: the turns and the straight moves start from rest.
      if (last_v_cmd_ != 0.0) {
        cmd->velocity = BrakeCommand(dt);
        return;
      }
      PlanApproachFrom(obs, cmd);
      return;
    case Step::kMoveOut:
      if (plan.path.empty()) {
        cmd->velocity = manoeuvre_.Update(obs.T_odom_base, dt, &finished);
      } else {
        const TrackingStatus s = follower_.Update(obs.T_map_base_estimate, dt);
        cmd->velocity = s.command;
        finished = s.reached || s.lost;
      }
      if (finished) approach_.step = Step::kPlan;
      return;
    case Step::kFirstTurn: {
      cmd->velocity = manoeuvre_.Update(obs.T_odom_base, dt, &finished);
      if (!finished) return;
      // From where the turn really ended (the plan assumed a perfect turn).
      const Pose2& here = obs.T_map_base_estimate;
      Path path = StraightPath(here, plan.T_frame_entry, config_.planner.sample_step_m);
      double end_speed = 0.0;
      if (plan.kind == ApproachKind::kTurnThenSmooth) {
        const PlanResult curve = PlanDockingPath(here, plan.T_frame_entry, config_.planner);
        path = curve.ok ? curve.path : plan.path;
        end_speed = config_.controller.max_speed_mps;
      }
      follower_.SetPath(std::move(path), config_.controller.approach_speed_mps, end_speed, 0.0,
                        config_.controller.approach_lateral_settle_m);
      ++path_version_;
      approach_.step = Step::kFollow;
      return;
    }
    case Step::kFollow: {
      const TrackingStatus s = follower_.Update(obs.T_map_base_estimate, dt);
      if (s.lost) {
        // Off the approach path by more than max_cross_track_m, most likely because the
        // localisation estimate jumped: stop and plan again from where it now says the robot is
        // (max_approach_plans bounds the plans). Docking itself runs on odometry and the scans.
        cmd->events.push_back("approach_off_path: " + Fmt(s.cross_track_m) +
                              " m off the approach path; re-planning");
        approach_.step = Step::kPlan;
        cmd->velocity = BrakeCommand(dt);
        return;
      }
      if (!s.reached) {
        cmd->velocity = s.command;
        return;
      }
      if (plan.kind == ApproachKind::kTurnDriveTurn) {
        manoeuvre_.StartTurn((approach_.T_odom_map * plan.T_frame_entry).yaw);
        approach_.step = Step::kFinalTurn;
        cmd->velocity = {};
        return;
      }
      break;
    }
    case Step::kFinalTurn:
      cmd->velocity = manoeuvre_.Update(obs.T_odom_base, dt, &finished);
      if (!finished) return;
      break;
  }
  StartDocking(obs, cmd);
  if (phase_ == Phase::kDock) StepDock(obs, cmd);
}

}  // namespace shelfdock::docking
