#include "eval/fault_injector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shelfdock::eval {
namespace {

using geometry::Pose2;

/// Where a mover crosses the docking path, and the unit vectors along and across it: the
/// Docker enters along the shelf's long side from the end nearer the robot's start.
struct Crossing {
  Eigen::Vector2d point;
  Eigen::Vector2d across;
};

Crossing CrossingPoint(const sim::Scenario& scenario, double docking_length_m, double across_m) {
  const sim::ScenarioShelf* target = scenario.FindShelf(scenario.target_shelf_id);
  const Pose2 T_map_shelf =
      target != nullptr ? target->T_map_shelf_preset.value_or(target->T_map_shelf) : Pose2();
  Eigen::Vector2d along(std::cos(T_map_shelf.yaw), std::sin(T_map_shelf.yaw));
  if (along.dot(scenario.T_map_robot_start.translation() - T_map_shelf.translation()) < 0.0) {
    along = -along;
  }
  return {T_map_shelf.translation() + along * (docking_length_m - across_m),
          Eigen::Vector2d(-along.y(), along.x())};
}

}  // namespace

void ApplyFaultToScenario(const FaultSpec& fault, double docking_length_m,
                          sim::Scenario* scenario) {
  const int id = scenario->target_shelf_id;
  const std::optional<sim::ShelfInstance> shelf = scenario->world.Shelf(id);
  const Crossing c = CrossingPoint(*scenario, docking_length_m, fault.across_m);
  constexpr double kHalfCrossing = 2.5;  // [m] movers walk this far either side of the path
  switch (fault.kind) {
    case FaultKind::kPersonCrossing:
    case FaultKind::kRobotPassing: {
      sim::PathMotion path;
      path.waypoints = {c.point - kHalfCrossing * c.across, c.point + kHalfCrossing * c.across};
      path.speed_mps = fault.speed_mps;
      path.start_offset_m = fault.amount * 2.0 * path.Length();
      if (fault.kind == FaultKind::kPersonCrossing) {
        sim::Person person;
        person.path = path;
        scenario->world.AddPerson(person);
      } else {
        sim::MovingRobot robot;
        robot.path = path;
        scenario->world.AddRobot(robot);
      }
      break;
    }
    case FaultKind::kPersonStanding: {
      sim::Person person;
      person.path.waypoints = {c.point + fault.offset.y * c.across};
      person.stride_m = 0.0;
      scenario->world.AddPerson(person);
      break;
    }
    case FaultKind::kShelfDisplaced:
      if (shelf) {
        const Pose2& T = shelf->T_world_shelf;
        scenario->world.SetShelfPose(
            id, Pose2(T.x + fault.offset.x, T.y + fault.offset.y, T.yaw + fault.offset.yaw));
      }
      break;
    case FaultKind::kWrongShelfCode:
      if (shelf) {
        // The same shelf where the map says, but its code is another shelf's.
        sim::ShelfInstance other = *shelf;
        other.id = id + 1;
        while (scenario->world.Shelf(other.id)) ++other.id;
        scenario->world.RemoveShelf(id);
        scenario->world.AddShelf(other);
      }
      break;
    case FaultKind::kNoShelf:
      scenario->world.RemoveShelf(id);
      break;
    default:
      break;
  }
}

FaultInjector::FaultInjector(FaultSpec fault, std::uint64_t seed)
    : fault_(fault), rng_(seed * 0xD1B54A32D192ED03ULL + 17) {}

void FaultInjector::ConfigureSensors(sim::SensorRigConfig* sensors) const {
  if (fault_.kind == FaultKind::kLidarBlackout) {
    sensors->blackout_start_s = fault_.start_s;
    sensors->blackout_duration_s = fault_.duration_s;
  }
  if (fault_.kind == FaultKind::kCameraBlind) sensors->camera_blind = true;
}

bool FaultInjector::Active(double since_entry_s) const {
  return std::isfinite(since_entry_s) && since_entry_s >= fault_.start_s &&
         since_entry_s < fault_.start_s + fault_.duration_s;
}

void FaultInjector::Spurious(geometry::LaserScan* scan) {
  // A burst: false returns on random beams at random short ranges (dust, a reflection).
  const int n = static_cast<int>(scan->ranges.size());
  if (n == 0) return;
  std::uniform_int_distribution<int> beam(0, n - 1);
  std::uniform_real_distribution<double> range(std::max(scan->range_min, 0.1), 4.0);
  for (int k = 0; k < static_cast<int>(fault_.amount); ++k) {
    scan->ranges[static_cast<std::size_t>(beam(rng_))] = range(rng_);
  }
}

void FaultInjector::SlipOdometry(bool slipping, docking::Observations* obs) {
  const Pose2 true_odom = obs->T_odom_base;
  if (!last_true_odom_) {
    last_true_odom_ = true_odom;
    reported_odom_ = true_odom;
    return;
  }
  Pose2 delta = last_true_odom_->inverse() * true_odom;
  if (slipping) {
    // The wheels turn faster than the robot moves: odometry counts motion that did not happen.
    const double k = 1.0 + fault_.amount;
    delta = Pose2(k * delta.x, k * delta.y, k * delta.yaw);
  }
  reported_odom_ = reported_odom_ * delta;
  last_true_odom_ = true_odom;
  obs->T_odom_base = reported_odom_;
}

void FaultInjector::CoverCode(geometry::GrayImage* image) {
  // Something covers the image from one edge to a little past its centre (where the code is
  // when the robot is near the goal): the code is seen only partly, if at all.
  std::uniform_int_distribution<int> side(0, 3);
  std::uniform_real_distribution<double> reach(0.35, 0.6);
  const int s = side(rng_);
  const double r = reach(rng_);
  for (int v = 0; v < image->height; ++v) {
    for (int u = 0; u < image->width; ++u) {
      const double fu = static_cast<double>(u) / image->width;
      const double fv = static_cast<double>(v) / image->height;
      const bool covered = (s == 0 && fu < r) || (s == 1 && fu > 1.0 - r) || (s == 2 && fv < r) ||
                           (s == 3 && fv > 1.0 - r);
      if (covered) image->at(u, v) = 90;
    }
  }
}

void FaultInjector::Apply(double t_s, double since_entry_s, sim::SensorReadings* readings,
                          docking::Observations* obs) {
  SlipOdometry(fault_.kind == FaultKind::kOdometrySlip && Active(since_entry_s), obs);
  if (fault_.kind == FaultKind::kLocalisationJump && t_s >= fault_.start_s) {
    obs->T_map_base_estimate = fault_.offset * obs->T_map_base_estimate;
  }
  if (readings->image && fault_.kind == FaultKind::kCameraPartial &&
      std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < fault_.amount) {
    CoverCode(&*readings->image);
  }

  const bool active = Active(since_entry_s);
  if (readings->scan != nullptr) {
    if (fault_.kind == FaultKind::kSpuriousPoints && active) {
      delivered_ = *readings->scan;
      Spurious(&delivered_);
      readings->scan = &delivered_;
    } else if (fault_.kind == FaultKind::kLateScans && (active || !pending_.empty())) {
      // Late scans keep their order: a scan never overtakes one still waiting.
      const double due = std::max(t_s + (active ? fault_.amount : 0.0),
                                  pending_.empty() ? t_s : pending_.back().due_s);
      pending_.push_back({due, *readings->scan});
      readings->scan = nullptr;
    } else if (fault_.kind == FaultKind::kDoubleScans && active) {
      pending_.push_back({t_s, *readings->scan});  // again in the next step
    }
  }
  if (readings->scan == nullptr && !pending_.empty() && pending_.front().due_s <= t_s) {
    delivered_ = std::move(pending_.front().scan);
    pending_.pop_front();
    readings->scan = &delivered_;
  }
}

}  // namespace shelfdock::eval
