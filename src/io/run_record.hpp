#pragma once

// Docking run record (`shelfdock dock --record FILE`): JSON Lines, one object per line.
//
//   {"type": "header", "scenario": name, "method": "continuous"|"stop-and-recognise", "seed": N,
//    "target_shelf": id, "preset": {"x","y","yaw"}, "shelves": [{"id","model","x","y","yaw",
//    "length","width","legs": [[x, y], ...]}], "robot": {"length","width"}}
//   {"type": "step", "t": s, "phase": "approach"|"dock"|"stand"|"verify"|"adjust"|"lift"|
//    "abort"|"done", "true": {"x","y","yaw"}, "odom": {...}, "estimate": {...} (localisation),
//    "cmd": {"v", "w"}, optional "scan": [[x, y], ...] (this step's scan in the world frame,
//    placed with the true pose), "detection": {...} (last accepted detection), "shelf": {...}
//    (fused shelf estimate), "path": [[x, y, yaw], ...] (when re-planned), "events": [text]}
//   {"type": "summary", ...the `shelfdock dock` result object...}: "result" ("success" or the
//    failure's snake_case name), "reason", "time_s" (docking area entry to end of lift),
//    "error_before_check" / "error_after_check" ({"x","y","yaw"} against the true shelf centre
//    in the shelf frame, {"x": null, "y": null, "yaw": null} when not reached; before = the
//    LiDAR-guided final error: the LiDAR-guided goal where it truly lay when the upward camera
//    first corrected it on the way in, else the pose at the stop for the check; after = the pose
//    at the lift),
//    "replans", "detections", "min_leg_clearance_m",
//    "method", "seed", "phases": {"approach_s" (before the entry, not in time_s), "dock_s",
//    "final_slow_s" (part of dock_s below 0.1 m/s), "stand_s" (baseline parking), "verify_s",
//    "adjust_s", "lift_s", "abort_s", "code_checks", "adjustments" (including those started
//    from the code seen on the way in, without a standing check first)}. Step events include
//    "camera_guide: ..." when the code seen while driving in moved the goal.
//
// Frames: everything is in the world (= map) frame. What the robot keeps in its odometry frame
// (detection, fused shelf, path) is drawn where the robot believes it is relative to itself,
// i.e. mapped with the true world-from-odometry transform at that step. Units: m, rad, s.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/docking_runner.hpp"
#include "sim/scenario.hpp"

namespace shelfdock::io {

/// Per-phase times of a run (eval::PhaseTimes) as {"approach_s", "dock_s", "final_slow_s",
/// "stand_s", "verify_s", "adjust_s", "lift_s", "abort_s", "code_checks", "adjustments"}.
nlohmann::json PhaseTimesJson(const eval::PhaseTimes& times);

/// The `shelfdock dock` result object (result, reason, time_s, errors, ...).
nlohmann::json DockingRunToJson(const eval::DockingRun& run);

/// The record of `run` (run with RunConfig::record) as its JSON Lines objects: header, steps,
/// summary. The replay page (`shelfdock dock --html`, `shelfdock view`) embeds these.
std::vector<nlohmann::json> RunRecordLines(const sim::Scenario& scenario,
                                           const geometry::Pose2& T_map_shelf_preset,
                                           const eval::DockingRun& run, double robot_length_m,
                                           double robot_width_m);

/// Writes the record of `run` (run with RunConfig::record) as JSON Lines; throws InputError when
/// the file cannot be written.
void WriteRunRecord(const std::string& path, const sim::Scenario& scenario,
                    const geometry::Pose2& T_map_shelf_preset, const eval::DockingRun& run,
                    double robot_length_m, double robot_width_m);

}  // namespace shelfdock::io
