#include "docking/approach_planner.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "docking/path_planner.hpp"
#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {

using geometry::Pose2;

/// The docking areas tried, longest first: max_entry_m down to the shortest allowed.
std::vector<double> EntryCandidates(double max_entry_m, const DockingConfig& config) {
  constexpr double kEntryStep_m = 0.25;
  std::vector<double> out;
  for (double d = max_entry_m; d >= config.min_entry_distance_m - 1e-9; d -= kEntryStep_m) {
    out.push_back(d);
  }
  if (out.empty() || out.back() > config.min_entry_distance_m + 1e-9) {
    out.push_back(std::min(max_entry_m, config.min_entry_distance_m));
  }
  return out;
}

double HeadingTo(const Pose2& from, const Pose2& to) {
  const Eigen::Vector2d d = to.translation() - from.translation();
  return std::atan2(d.y(), d.x());
}

struct Checker {
  const FreeSpace& free_space;
  const DockingConfig& config;
  double margin() const { return config.safety.obstacle_margin_m; }
  bool PathClear(const Path& path) const {
    return free_space.PathClearance(path, config.safety) >= margin();
  }
  bool TurnClear(const Pose2& pose) const {
    return free_space.TurnClearance(pose, config.safety) >= margin();
  }
};

/// Curve from `from` to `entry` if it is feasible and clear.
std::optional<Path> SmoothTo(const Pose2& from, const Pose2& entry, const Checker& check) {
  const PlanResult plan = PlanDockingPath(from, entry, check.config.planner);
  if (!plan.ok || !check.PathClear(plan.path)) return std::nullopt;
  return plan.path;
}

}  // namespace

std::string_view ToString(ApproachKind kind) {
  switch (kind) {
    case ApproachKind::kDockNow:
      return "dock_now";
    case ApproachKind::kSmooth:
      return "smooth";
    case ApproachKind::kTurnThenSmooth:
      return "turn_then_smooth";
    case ApproachKind::kTurnDriveTurn:
      return "turn_drive_turn";
    case ApproachKind::kMoveOut:
      return "move_out";
  }
  return "unknown";
}

ApproachPlan PlanApproach(const Pose2& T_frame_base, const Pose2& T_frame_goal, double max_entry_m,
                          const FreeSpace& free_space, const DockingConfig& config,
                          bool allow_move_out) {
  const Checker check{free_space, config};
  ApproachPlan plan;
  const std::vector<double> entries = EntryCandidates(max_entry_m, config);
  auto entry_at = [&](double d) { return T_frame_goal * Pose2(-d, 0.0, 0.0); };

  // Inside the docking area already: the docking stage plans its own path from here.
  const Pose2 in_goal = T_frame_goal.inverse() * T_frame_base;
  if (-in_goal.x <= max_entry_m + config.entry_tolerance_m &&
      std::abs(in_goal.y) <= config.area_half_width_m &&
      std::abs(geometry::WrapAngle(in_goal.yaw)) <= config.area_max_heading_rad) {
    const PlanResult direct = PlanDockingPath(T_frame_base, T_frame_goal, config.planner);
    if (direct.ok && check.PathClear(direct.path)) {
      plan.ok = true;
      plan.kind = ApproachKind::kDockNow;
      plan.entry_distance_m = std::max(0.0, -in_goal.x);
      plan.T_frame_entry = T_frame_base;
      return plan;
    }
  }
  // Candidates (kind, docking area) in order of preference: a longer straight gives the LiDAR
  // more scans, a smooth entry saves the stop; each kind costs the straight length it is worth.
  struct Candidate {
    double score;
    ApproachKind kind;
    double d;
  };
  std::vector<Candidate> candidates;
  for (double d : entries) {
    candidates.push_back({d, ApproachKind::kSmooth, d});
    candidates.push_back({d - config.turn_penalty_m, ApproachKind::kTurnThenSmooth, d});
    candidates.push_back({d - 2.0 * config.turn_penalty_m, ApproachKind::kTurnDriveTurn, d});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  const bool can_turn_here = check.TurnClear(T_frame_base);
  for (const Candidate& c : candidates) {
    const Pose2 entry = entry_at(c.d);
    const Pose2 turned(T_frame_base.x, T_frame_base.y, HeadingTo(T_frame_base, entry));
    if (c.kind == ApproachKind::kSmooth) {
      if (auto path = SmoothTo(T_frame_base, entry, check)) {
        return {true, c.kind, c.d, entry, 0.0, {}, std::move(*path), {}};
      }
    } else if (c.kind == ApproachKind::kTurnThenSmooth) {
      if (!can_turn_here) continue;
      if (auto path = SmoothTo(turned, entry, check)) {
        return {true, c.kind, c.d, entry, turned.yaw, {}, std::move(*path), {}};
      }
    } else {
      if (!can_turn_here || !check.TurnClear(entry)) continue;
      Path line = StraightPath(turned, entry, config.planner.sample_step_m);
      if (!check.PathClear(line)) continue;
      return {true, c.kind, c.d, entry, turned.yaw, {}, std::move(line), {}};
    }
  }
  if (!allow_move_out) {
    plan.reason = "no approach from here without moving out first";
    return plan;
  }
  // A move out is worth it only when an approach exists from where it ends.
  auto leads_somewhere = [&](const Pose2& to) {
    return check.TurnClear(to) &&
           PlanApproach(to, T_frame_goal, max_entry_m, free_space, config, false).ok;
  };
  // Nothing from here: a straight move along the heading (forward or reversing, shorter first)
  // to a place where the robot can turn, as long as the move itself keeps the clearance it has.
  constexpr double kMoveStep_m = 0.1;
  const double max_move_m = config.max_move_out_m;
  const double now_clear = free_space.Clearance(T_frame_base, config.safety);
  // A move out starts close to something: it may lose a centimetre of the clearance it has,
  // never touch.
  constexpr double kMoveMayLose_m = 0.01;
  const double move_margin = std::max(0.0, std::min(check.margin(), now_clear - kMoveMayLose_m));
  for (double s = kMoveStep_m; s <= max_move_m + 1e-9; s += kMoveStep_m) {
    for (double sign : {-1.0, 1.0}) {
      const Pose2 to = T_frame_base * Pose2(sign * s, 0.0, 0.0);
      Path line = StraightPath(T_frame_base, to, config.planner.sample_step_m);
      bool clear = true;
      for (const PathPoint& p : line.points) {
        const Pose2 pose(p.pose.x, p.pose.y, T_frame_base.yaw);
        if (free_space.Clearance(pose, config.safety) < move_margin) {
          clear = false;
          break;
        }
      }
      if (!clear || !leads_somewhere(to)) continue;
      plan.ok = true;
      plan.kind = ApproachKind::kMoveOut;
      plan.T_frame_move_to = to;
      plan.entry_distance_m = entries.front();
      plan.T_frame_entry = entry_at(entries.front());
      return plan;
    }
  }
  // Still nothing (a wall alongside): a forward arc away from it to where a turn is free; the
  // gentler arcs swing the tail less toward the wall.
  for (double length = kMoveStep_m; length <= max_move_m + 1e-9; length += kMoveStep_m) {
    for (const auto& [side, k] : {std::pair{-1.0, config.planner.max_curvature_1pm},
                                  {1.0, config.planner.max_curvature_1pm},
                                  {-1.0, 0.5 * config.planner.max_curvature_1pm},
                                  {1.0, 0.5 * config.planner.max_curvature_1pm},
                                  {-1.0, 0.25 * config.planner.max_curvature_1pm},
                                  {1.0, 0.25 * config.planner.max_curvature_1pm}}) {
      Path arc;
      const int n = std::max(2, static_cast<int>(std::ceil(length / config.planner.sample_step_m)));
      for (int i = 0; i <= n; ++i) {
        const double s_m = length * i / n;
        const double a = side * k * s_m;
        const Pose2 local(std::sin(a) / (side * k), (1.0 - std::cos(a)) / (side * k), a);
        arc.points.push_back({T_frame_base * local, s_m, side * k});
      }
      if (free_space.PathClearance(arc, config.safety) < move_margin) continue;
      if (!leads_somewhere(arc.Goal())) continue;
      plan.ok = true;
      plan.kind = ApproachKind::kMoveOut;
      plan.T_frame_move_to = arc.Goal();
      plan.path = std::move(arc);
      plan.entry_distance_m = entries.front();
      plan.T_frame_entry = entry_at(entries.front());
      return plan;
    }
  }
  plan.reason = "no approach to the docking area's entry (" + std::to_string(entries.front()) +
                " m down to " + std::to_string(entries.back()) +
                " m): every curve, turn or straight move from here comes within " +
                std::to_string(check.margin()) + " m of an obstacle";
  return plan;
}

}  // namespace shelfdock::docking
