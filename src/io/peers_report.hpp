#pragma once

// Reports of `shelfdock eval peers`: the accuracy and time table per scene set with each peer's
// ratio to shelfdock, the ICP peer against its speed target, the search-work table, as Markdown
// lines, and every number as JSON. Units in JSON: m, rad, s; tables print mm, mrad, us.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/peer_comparison.hpp"

namespace shelfdock::io {

/// Markdown table: accuracy and time per scan for each scene set and method.
std::vector<std::string> PeerTableLines(const std::vector<eval::PeerRow>& rows);
/// Issue 9's speed target: shelfdock at least this many times faster than the ICP peer (median
/// time per scan).
inline constexpr double kIcpSpeedTarget = 20.0;

/// What the CLI says when the ICP peer is not in the build.
inline constexpr const char* kIcpNotBuilt =
    "ICP peer (PCL) not built: configure with -DSHELFDOCK_WITH_PCL=ON (needs libpcl-dev)";

/// Markdown list: per scene set, the ICP peer's median time per scan over shelfdock's against
/// kIcpSpeedTarget (met, or missed by how much). Without ICP rows: kIcpNotBuilt.
std::vector<std::string> IcpTargetLines(const std::vector<eval::PeerRow>& rows);
/// Markdown table: leg-search checks and time, pruned against exhaustive, per scene set.
std::vector<std::string> SearchTableLines(const std::vector<eval::SearchRow>& rows);
/// {"accuracy": [{"set", "method", "scenes", "successes", "success_rate", "position_m": {p50,
/// p95}, "heading_rad", "time_s", "ratio_to_shelfdock": {"position_p95", "heading_p95",
/// "time_p50"}}], "icp": {"built", "speed_target", "sets": [{"set", "time_ratio", "met"}]},
/// "search": [...]}.
nlohmann::json PeersJson(const std::vector<eval::PeerRow>& rows,
                         const std::vector<eval::SearchRow>& search);

}  // namespace shelfdock::io
