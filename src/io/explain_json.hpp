#pragma once

// What the explain page (`shelfdock detect --html FILE`) draws of one scan besides the detector's
// own output: every valid point with its cluster, the points the trailing-point filter removed,
// the ROI, and the clusters with their screening result. The detector is run on the side of this
// (Detector::Detect with explain = true); this only re-runs its public preprocessing (paper 3.1)
// so that perception stays free of output formats.
//
//   {"points": [[x, y, cluster], ...] (kept points, lidar frame; cluster indexes "clusters"),
//    "trailing": [[x, y], ...] (removed by Eq. 1),
//    "roi": {"x", "y", "r"} | null (no preset: the whole scan),
//    "clusters": [{"x", "y", "extent", "points", "in_roi", "candidate"}] (centroid, [m])}
//
// Frames: everything in the scan's own frame (`lidar`). Units: m.

#include <optional>

#include <nlohmann/json.hpp>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "perception/detector.hpp"

namespace shelfdock::io {

/// The preprocessing view of `scan` as `detector` saw it (with `T_lidar_preset` if given).
nlohmann::json ExplainGeometryJson(const geometry::LaserScan& scan,
                                   const perception::Detector& detector,
                                   const std::optional<geometry::Pose2>& T_lidar_preset);

/// The shelf models as {"name", "length", "width", "leg": {"shape", "length", "width"}}, for
/// drawing hypotheses and detections with their outline.
nlohmann::json ModelsJson(const std::vector<geometry::ShelfModel>& models);

}  // namespace shelfdock::io
