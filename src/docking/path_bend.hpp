#pragma once

#include <optional>

#include "docking/path.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::docking {

/// Moves the end of a path the robot is following to a goal that moved a little (a new
/// detection, the code under the shelf), without planning afresh. Planning from the robot's
/// pose starts the new path with the robot's heading but not its turn rate, so each re-plan
/// kicks the controller; several of them close to the goal, while the robot still swings from
/// the last, made it weave by up to 0.19 rad and stop 18 mm off. Bending leaves the path as it
/// is at the robot and deforms what is ahead so that it ends on the new goal: a point at arc
/// length s moves by w(u) of the rigid motion that takes the old goal onto the new one, with
/// u = (s - s_from) / (length - s_from) and the smoothstep w = 3u^2 - 2u^3 (0 with zero slope
/// at the robot, 1 with zero slope at the goal, so the last stretch is the old final straight
/// moved rigidly onto the new goal). Headings and curvatures are those of the bent curve.
/// Empty when nothing is left ahead of s_from.
std::optional<Path> BendPathToGoal(const Path& path, double s_from, const geometry::Pose2& goal);

}  // namespace shelfdock::docking
