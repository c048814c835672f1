#include "eval/peers/corner_peer.hpp"

#include <cmath>
#include <limits>

#include "perception/preprocess.hpp"

namespace shelfdock::eval::peers {
namespace {

/// A right-angle corner: the centre and long-side heading it implies for one model.
struct Corner {
  int model = -1;
  Eigen::Vector2d centre;
  double yaw_rad = 0.0;  ///< of the long side, modulo pi
};

/// Corners that agree on one shelf.
struct Group {
  int model = -1;
  Eigen::Vector2d centre_sum = Eigen::Vector2d::Zero();
  /// Sum of (cos k yaw, sin k yaw), k = 2 (4 for a square): a heading's symmetric twins add up.
  Eigen::Vector2d heading_sum = Eigen::Vector2d::Zero();
  int corners = 0;

  Eigen::Vector2d Centre() const { return centre_sum / corners; }
};

}  // namespace

std::optional<PeerEstimate> CornerPeerDetect(const geometry::LaserScan& scan,
                                             const std::optional<geometry::Pose2>& T_lidar_preset,
                                             const std::vector<geometry::ShelfModel>& models,
                                             const perception::DetectorConfig& detector,
                                             const CornerPeerConfig& config) {
  const perception::PreprocessOutput pre =
      perception::Preprocess(perception::ScanToPoints(scan), scan.angle_increment, T_lidar_preset,
                             models, detector.preprocess);
  std::vector<Eigen::Vector2d> legs;
  for (const perception::Cluster& c : pre.candidates) legs.push_back(c.centroid);
  const int n = static_cast<int>(legs.size());
  const double tol = config.length_tolerance_m;

  std::vector<Corner> corners;
  for (int v = 0; v < n; ++v) {
    for (int a = 0; a < n; ++a) {
      if (a == v) continue;
      const Eigen::Vector2d va = legs[a] - legs[v];
      const double la = va.norm();
      for (int b = 0; b < n; ++b) {
        if (b == v || b == a) continue;
        const Eigen::Vector2d vb = legs[b] - legs[v];
        const double lb = vb.norm();
        if (std::abs(va.dot(vb)) > config.max_corner_cos * la * lb) continue;
        for (int m = 0; m < static_cast<int>(models.size()); ++m) {
          // va along the long side, vb along the short one.
          if (std::abs(la - models[m].length_m) > tol || std::abs(lb - models[m].width_m) > tol) {
            continue;
          }
          // The pair a-b at the model's diagonal confirms the corner.
          if (std::abs((legs[a] - legs[b]).norm() - models[m].Diagonal()) > tol) continue;
          corners.push_back({m, 0.5 * (legs[a] + legs[b]), std::atan2(va.y(), va.x())});
        }
      }
    }
  }

  std::vector<Group> groups;
  for (const Corner& c : corners) {
    Group* home = nullptr;
    for (Group& g : groups) {
      if (g.model == c.model && (g.Centre() - c.centre).norm() < config.group_radius_m) {
        home = &g;
        break;
      }
    }
    if (home == nullptr) {
      groups.push_back({c.model});
      home = &groups.back();
    }
    home->centre_sum += c.centre;
    const double k = models[c.model].IsSquare() ? 4.0 : 2.0;
    home->heading_sum += Eigen::Vector2d(std::cos(k * c.yaw_rad), std::sin(k * c.yaw_rad));
    ++home->corners;
  }

  const Group* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const Group& g : groups) {
    const double d =
        T_lidar_preset ? (g.Centre() - T_lidar_preset->translation()).norm() : g.Centre().norm();
    if (best == nullptr || g.corners > best->corners ||
        (g.corners == best->corners && d < best_distance)) {
      best = &g;
      best_distance = d;
    }
  }
  if (best == nullptr) return std::nullopt;
  const geometry::ShelfModel& model = models[best->model];
  const Eigen::Vector2d c = best->Centre();
  geometry::Pose2 T_lidar_shelf(c.x(), c.y(), 0.0);
  const double k = model.IsSquare() ? 4.0 : 2.0;
  const double yaw = std::atan2(best->heading_sum.y(), best->heading_sum.x()) / k;
  T_lidar_shelf.yaw = ResolvePeerHeading(yaw, T_lidar_shelf, T_lidar_preset, model.HeadingPeriod());
  // Three legs make one right-angle corner; a second corner means the fourth leg was seen.
  return PeerEstimate{model.name, T_lidar_shelf, best->corners >= 2 ? 4 : 3};
}

}  // namespace shelfdock::eval::peers
