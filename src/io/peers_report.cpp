#include "io/peers_report.hpp"

#include <cmath>

#include "io/report_format.hpp"

namespace shelfdock::io {
namespace {

nlohmann::json Json(double v) { return JsonNumber(v); }

nlohmann::json Json(const eval::Quantiles& q) {
  return {{"p50", Json(q.p50)}, {"p95", Json(q.p95)}};
}

/// shelfdock's row of the same scene set.
const eval::PeerRow* Reference(const std::vector<eval::PeerRow>& rows, const std::string& set) {
  for (const auto& r : rows) {
    if (r.set == set && r.method == eval::PeerMethod::kShelfdock) return &r;
  }
  return nullptr;
}

/// An ICP row, shelfdock's row of the same set, and how many times faster shelfdock is there
/// (median time per scan).
struct IcpPair {
  const eval::PeerRow* icp;
  const eval::PeerRow* ref;
  double ratio;
};

std::vector<IcpPair> IcpPairs(const std::vector<eval::PeerRow>& rows) {
  std::vector<IcpPair> out;
  for (const auto& r : rows) {
    if (r.method != eval::PeerMethod::kIcp) continue;
    if (const eval::PeerRow* ref = Reference(rows, r.set)) {
      out.push_back({&r, ref, r.time_s.p50 / ref->time_s.p50});
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> PeerTableLines(const std::vector<eval::PeerRow>& rows) {
  std::vector<std::string> out;
  out.push_back(
      "| scene set | method | success | position p50 / p95 [mm] | heading p50 / p95 [mrad] | "
      "time p50 / p95 [us] | x shelfdock: position p95 / heading p95 / time p50 |");
  out.push_back("|---|---|---|---|---|---|---|");
  for (const auto& r : rows) {
    const eval::PeerRow* ref = Reference(rows, r.set);
    std::string ratio = "-";
    if (ref != nullptr && r.method != eval::PeerMethod::kShelfdock) {
      ratio = FormatNumber(r.position_m.p95 / ref->position_m.p95, 1.0, 2) + " / " +
              FormatNumber(r.heading_rad.p95 / ref->heading_rad.p95, 1.0, 2) + " / " +
              FormatNumber(r.time_s.p50 / ref->time_s.p50, 1.0, 2);
    }
    out.push_back(
        "| " + r.set + " | " + std::string(eval::PeerMethodName(r.method)) + " | " +
        FormatNumber(r.SuccessRate(), 100.0, 1) + " % (" + std::to_string(r.successes) + "/" +
        std::to_string(r.scenes) + ") | " + FormatNumber(r.position_m.p50, 1e3) + " / " +
        FormatNumber(r.position_m.p95, 1e3) + " | " + FormatNumber(r.heading_rad.p50, 1e3) + " / " +
        FormatNumber(r.heading_rad.p95, 1e3) + " | " + FormatNumber(r.time_s.p50, 1e6, 0) + " / " +
        FormatNumber(r.time_s.p95, 1e6, 0) + " | " + ratio + " |");
  }
  return out;
}

std::vector<std::string> IcpTargetLines(const std::vector<eval::PeerRow>& rows) {
  const auto pairs = IcpPairs(rows);
  if (pairs.empty()) return {kIcpNotBuilt};
  std::vector<std::string> out;
  for (const auto& [icp, ref, ratio] : pairs) {
    const std::string verdict =
        ratio >= kIcpSpeedTarget
            ? "met"
            : "**missed** by " + FormatNumber(kIcpSpeedTarget / ratio, 1.0, 2) + "x";
    out.push_back("- " + icp->set + ": shelfdock " + FormatNumber(ratio, 1.0, 1) +
                  "x faster than ICP (median " + FormatNumber(ref->time_s.p50, 1e6, 0) +
                  " us against " + FormatNumber(icp->time_s.p50, 1e6, 0) +
                  " us per scan; target >= " + FormatNumber(kIcpSpeedTarget, 1.0, 0) +
                  "x: " + verdict + ")");
  }
  return out;
}

std::vector<std::string> SearchTableLines(const std::vector<eval::SearchRow>& rows) {
  std::vector<std::string> out;
  out.push_back(
      "| scene set | leg candidates (mean) | pruned checks (mean) | exhaustive checks (mean) | "
      "exhaustive / pruned | pruned time p50 [us] | exhaustive time p50 [us] |");
  out.push_back("|---|---|---|---|---|---|---|");
  for (const auto& r : rows) {
    out.push_back("| " + r.set + " | " + FormatNumber(r.mean_candidates, 1.0, 1) + " | " +
                  FormatNumber(r.mean_pruned_checks, 1.0, 0) + " | " +
                  FormatNumber(r.mean_exhaustive_checks, 1.0, 0) + " | " +
                  FormatNumber(r.mean_exhaustive_checks / r.mean_pruned_checks, 1.0, 1) + "x | " +
                  FormatNumber(r.pruned_time_s.p50, 1e6, 1) + " | " +
                  FormatNumber(r.exhaustive_time_s.p50, 1e6, 0) + " |");
  }
  return out;
}

nlohmann::json PeersJson(const std::vector<eval::PeerRow>& rows,
                         const std::vector<eval::SearchRow>& search) {
  nlohmann::json accuracy = nlohmann::json::array();
  for (const auto& r : rows) {
    nlohmann::json row{{"set", r.set},
                       {"method", std::string(eval::PeerMethodName(r.method))},
                       {"scenes", r.scenes},
                       {"successes", r.successes},
                       {"success_rate", r.SuccessRate()},
                       {"position_m", Json(r.position_m)},
                       {"heading_rad", Json(r.heading_rad)},
                       {"time_s", Json(r.time_s)}};
    if (const eval::PeerRow* ref = Reference(rows, r.set)) {
      row["ratio_to_shelfdock"] = {{"position_p95", Json(r.position_m.p95 / ref->position_m.p95)},
                                   {"heading_p95", Json(r.heading_rad.p95 / ref->heading_rad.p95)},
                                   {"time_p50", Json(r.time_s.p50 / ref->time_s.p50)}};
    }
    accuracy.push_back(row);
  }
  nlohmann::json work = nlohmann::json::array();
  for (const auto& r : search) {
    work.push_back({{"set", r.set},
                    {"scenes", r.scenes},
                    {"mean_candidates", r.mean_candidates},
                    {"mean_pruned_checks", r.mean_pruned_checks},
                    {"mean_exhaustive_checks", r.mean_exhaustive_checks},
                    {"pruned_time_s", Json(r.pruned_time_s)},
                    {"exhaustive_time_s", Json(r.exhaustive_time_s)}});
  }
  nlohmann::json icp_sets = nlohmann::json::array();
  for (const auto& [icp, ref, ratio] : IcpPairs(rows)) {
    icp_sets.push_back(
        {{"set", icp->set}, {"time_ratio", Json(ratio)}, {"met", ratio >= kIcpSpeedTarget}});
  }
  const nlohmann::json icp{
      {"built", !icp_sets.empty()}, {"speed_target", kIcpSpeedTarget}, {"sets", icp_sets}};
  return {{"accuracy", accuracy}, {"icp", icp}, {"search", work}};
}

}  // namespace shelfdock::io
