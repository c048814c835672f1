// The JSON form of detector results, shared by `shelfdock detect` and the Python module.
#include "io/detection_json.hpp"

#include "perception/frames.hpp"

namespace shelfdock::io {
namespace {

nlohmann::json PoseJson(const geometry::Pose2& T) {
  return {{"x", T.x}, {"y", T.y}, {"yaw", T.yaw}};
}

}  // namespace

nlohmann::json RunnerUpToJson(const perception::RunnerUp& r) {
  return {{"model", r.model}, {"chi2_margin", r.chi2_margin}};
}

nlohmann::json DetectionToJson(const perception::Detection& d,
                               const std::optional<geometry::Pose2>& T_base_lidar,
                               const std::optional<geometry::Pose2>& T_map_base) {
  nlohmann::json legs = nlohmann::json::array();
  for (const auto& l : d.legs) legs.push_back({l.x(), l.y()});
  nlohmann::json cov = nlohmann::json::array();
  for (int r = 0; r < 3; ++r)
    cov.push_back({d.covariance(r, 0), d.covariance(r, 1), d.covariance(r, 2)});
  nlohmann::json j = {{"model", d.model},
                      {"x", d.T_lidar_shelf.x},
                      {"y", d.T_lidar_shelf.y},
                      {"yaw", d.T_lidar_shelf.yaw},
                      {"length", d.length_m},
                      {"width", d.width_m},
                      {"legs", legs},
                      {"legs_used", d.legs_used},
                      {"err_sum", d.err_sum},
                      {"cost", d.cost},
                      {"covariance", cov},
                      {"fit", PoseJson(d.FusionPose())},
                      {"confidence", d.confidence},
                      {"legs_visible", d.legs_visible},
                      {"legs_occluded", d.legs_occluded},
                      {"interior_points", d.interior_points},
                      {"leg_width_error", d.leg_width_error_m},
                      {"leg_width_bias", d.leg_width_bias_m}};
  if (d.runner_up) j["runner_up"] = RunnerUpToJson(*d.runner_up);
  if (T_base_lidar) j["base"] = PoseJson(perception::ShelfInBase(d, *T_base_lidar));
  if (T_map_base) {
    j["map"] =
        PoseJson(perception::ShelfInMap(d, T_base_lidar.value_or(geometry::Pose2()), *T_map_base));
  }
  return j;
}

nlohmann::json DetectionStatsToJson(const perception::DetectionStats& s) {
  return {{"valid_points", s.valid_points},
          {"roi_points", s.roi_points},
          {"clusters", s.clusters},
          {"trailing_removed", s.trailing_removed},
          {"leg_candidates", s.leg_candidates},
          {"leg_sets", s.leg_sets},
          {"completed_sets", s.completed_sets},
          {"model_pairs", s.model_pairs},
          {"hypotheses", s.hypotheses},
          {"range_noise_m", s.range_noise_m},
          {"width_bloom_rad", s.width_bloom_rad},
          {"depth_steps", s.depth_steps},
          {"bridged_steps", s.bridged_steps},
          {"stray_returns", s.stray_returns},
          {"rejected",
           {{"fit", s.rejected.fit},
            {"model", s.rejected.model},
            {"three_leg_error", s.rejected.three_leg_error},
            {"hidden_leg_no_preset", s.rejected.hidden_leg_no_preset},
            {"blended_legs", s.rejected.blended_legs},
            {"leg_seen_through", s.rejected.leg_seen_through},
            {"low_confidence", s.rejected.low_confidence},
            {"lost_legs", s.rejected.lost_legs},
            {"off_preset", s.rejected.off_preset}}}};
}

nlohmann::json HypothesisToJson(const perception::HypothesisRecord& h) {
  nlohmann::json legs = nlohmann::json::array();
  for (const auto& l : h.legs) legs.push_back({l.x(), l.y()});
  return {{"model", h.model},
          {"verdict", perception::VerdictName(h.verdict)},
          {"x", h.T_lidar_shelf.x},
          {"y", h.T_lidar_shelf.y},
          {"yaw", h.T_lidar_shelf.yaw},
          {"legs", legs},
          {"legs_blended", h.legs_blended},
          {"legs_flush", h.legs_flush},
          {"legs_edge_blends", h.legs_edge_blends},
          {"err_sum", h.err_sum},
          {"confidence", h.confidence},
          {"legs_visible", h.legs_visible},
          {"legs_occluded", h.legs_occluded},
          {"legs_seen_through", h.legs_seen_through},
          {"interior_points", h.interior_points},
          {"foreign_legs_inside", h.foreign_legs_inside},
          {"leg_width_error", h.leg_width_error_m},
          {"leg_width_bias", h.leg_width_bias_m},
          {"width_bloom_rad", h.width_bloom_rad}};
}

nlohmann::json CandidateToJson(const perception::CandidateRecord& c) {
  return {{"x", c.centre.x()},    {"y", c.centre.y()},
          {"returns", c.returns}, {"beams", {c.first_beam, c.last_beam}},
          {"extent", c.extent_m}, {"completed", c.completed},
          {"blended", c.blended}, {"flush", c.flush}};
}

nlohmann::json DetectionResultToJson(const perception::DetectionResult& result, bool explain,
                                     const std::optional<geometry::Pose2>& T_base_lidar,
                                     const std::optional<geometry::Pose2>& T_map_base) {
  nlohmann::json dets = nlohmann::json::array();
  for (const auto& d : result.detections)
    dets.push_back(DetectionToJson(d, T_base_lidar, T_map_base));
  nlohmann::json out{{"detections", dets}, {"stats", DetectionStatsToJson(result.stats)}};
  if (explain) {
    nlohmann::json hyps = nlohmann::json::array();
    for (const auto& h : result.hypotheses) hyps.push_back(HypothesisToJson(h));
    out["hypotheses"] = hyps;
    nlohmann::json candidates = nlohmann::json::array();
    for (const auto& c : result.candidates) candidates.push_back(CandidateToJson(c));
    out["candidates"] = candidates;
  }
  return out;
}

}  // namespace shelfdock::io
