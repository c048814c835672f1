#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "geometry/pose2.hpp"
#include "perception/detection.hpp"

namespace shelfdock::io {

/// One detection as `shelfdock detect` prints it: model, x, y, yaw (lidar frame), length,
/// width, legs, legs_used, err_sum, cost, covariance (3x3 rows), confidence, legs_visible,
/// legs_occluded, interior_points, leg_width_error, leg_width_bias; "runner_up" (RunnerUpToJson)
/// when another model fitted the legs too; plus "base" ({x, y, yaw}) when
/// `T_base_lidar` is given and "map" when `T_map_base` is given (lidar = base without an
/// extrinsic).
nlohmann::json DetectionToJson(const perception::Detection& d,
                               const std::optional<geometry::Pose2>& T_base_lidar = std::nullopt,
                               const std::optional<geometry::Pose2>& T_map_base = std::nullopt);

/// The next-best model of a detection: {"model", "chi2_margin"}.
nlohmann::json RunnerUpToJson(const perception::RunnerUp& r);

/// The scan's pipeline counts ("stats"), with "rejected" per reason.
nlohmann::json DetectionStatsToJson(const perception::DetectionStats& s);

/// One explained hypothesis (`detect --explain`): its legs, evidence and verdict.
nlohmann::json HypothesisToJson(const perception::HypothesisRecord& h);

/// One leg candidate as the search saw it (`detect --explain`): its centre, returns, beams,
/// extent and whether the completion cut it (blended, flush).
nlohmann::json CandidateToJson(const perception::CandidateRecord& c);

/// The whole line `shelfdock detect` prints for one scan: {"detections": [...], "stats": {...}}
/// and, when the result was explained, "hypotheses" and "candidates". The CLI and the Python
/// module both use it, so their fields cannot drift apart.
nlohmann::json DetectionResultToJson(
    const perception::DetectionResult& result, bool explain,
    const std::optional<geometry::Pose2>& T_base_lidar = std::nullopt,
    const std::optional<geometry::Pose2>& T_map_base = std::nullopt);

}  // namespace shelfdock::io
