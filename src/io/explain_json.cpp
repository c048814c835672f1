#include "io/explain_json.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "perception/preprocess.hpp"

namespace shelfdock::io {
namespace {

using nlohmann::json;

// Millimetres are plenty for drawing and keep a page of many scans small.
double Mm(double v) { return std::round(v * 1000.0) / 1000.0; }

}  // namespace

json ExplainGeometryJson(const geometry::LaserScan& scan, const perception::Detector& detector,
                         const std::optional<geometry::Pose2>& T_lidar_preset) {
  const std::vector<geometry::ShelfModel>& models = detector.models();
  const perception::PreprocessConfig& config = detector.config().preprocess;
  // The same calls, on the same input, as Detector::Detect makes.
  const std::vector<perception::ScanPoint> valid = perception::ScanToPoints(scan);
  const perception::PreprocessOutput pre =
      perception::Preprocess(valid, scan.angle_increment, T_lidar_preset, models, config);

  std::vector<int> cluster_of(pre.points.size(), -1);
  json clusters = json::array();
  std::vector<char> is_candidate(pre.spans.size(), 0);
  for (const auto& c : pre.candidates) {
    if (c.span >= 0) is_candidate[static_cast<std::size_t>(c.span)] = 1;
  }
  // Preprocess's ROI: roi_gamma times the longest model diagonal around the preset centre,
  // applied to whole clusters by their centroid.
  double longest_diagonal = 0.0;
  for (const auto& m : models) longest_diagonal = std::max(longest_diagonal, m.Diagonal());
  const double roi_radius = config.roi_gamma * longest_diagonal;
  for (std::size_t si = 0; si < pre.spans.size(); ++si) {
    const perception::ClusterSpan& span = pre.spans[si];
    for (std::size_t k = span.begin; k < span.end; ++k) cluster_of[k] = static_cast<int>(si);
    const bool in_roi =
        !T_lidar_preset || (span.centroid - T_lidar_preset->translation()).norm() <= roi_radius;
    clusters.push_back({{"x", Mm(span.centroid.x())},
                        {"y", Mm(span.centroid.y())},
                        {"extent", Mm(span.extent_m)},
                        {"points", span.size()},
                        {"in_roi", in_roi},
                        {"candidate", is_candidate[si] != 0}});
  }

  json points = json::array();
  std::vector<char> kept_beam;
  for (std::size_t k = 0; k < pre.points.size(); ++k) {
    const perception::ScanPoint& p = pre.points[k];
    points.push_back({Mm(p.p.x()), Mm(p.p.y()), cluster_of[k]});
    const auto beam = static_cast<std::size_t>(p.beam);
    if (beam >= kept_beam.size()) kept_beam.resize(beam + 1, 0);
    kept_beam[beam] = 1;
  }
  json trailing = json::array();
  for (const perception::ScanPoint& p : valid) {
    const auto beam = static_cast<std::size_t>(p.beam);
    if (beam < kept_beam.size() && kept_beam[beam]) continue;
    trailing.push_back({Mm(p.p.x()), Mm(p.p.y())});
  }

  json roi = nullptr;
  if (T_lidar_preset) {
    roi = {{"x", T_lidar_preset->x}, {"y", T_lidar_preset->y}, {"r", roi_radius}};
  }
  return {{"points", points}, {"trailing", trailing}, {"roi", roi}, {"clusters", clusters}};
}

json ModelsJson(const std::vector<geometry::ShelfModel>& models) {
  json out = json::array();
  for (const auto& m : models) {
    out.push_back({{"name", m.name},
                   {"length", m.length_m},
                   {"width", m.width_m},
                   {"leg",
                    {{"shape", m.leg.shape == geometry::LegShape::kCircle ? "circle" : "rectangle"},
                     {"length", m.leg.length_m},
                     {"width", m.leg.width_m}}}});
  }
  return out;
}

}  // namespace shelfdock::io
