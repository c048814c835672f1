// The ICP peer: all of its PCL use in this one translation unit (PCL's templates are slow to
// compile); built only with SHELFDOCK_WITH_PCL.
#include "eval/peers/icp_peer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include <pcl/console/print.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/icp.h>
#include <pcl/registration/transformation_estimation_2D.h>
#include <pcl/search/kdtree.h>

#include "perception/preprocess.hpp"

namespace shelfdock::eval::peers {
namespace {

using Point = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Point>;
using Tree = pcl::search::KdTree<Point>;

/// PCL's ICP with its iteration count readable (PCL keeps it protected).
class Icp : public pcl::IterativeClosestPoint<Point, Point> {
 public:
  int Iterations() const { return nr_iterations_; }
};

Point ToPoint(const Eigen::Vector2d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), 0.0f};
}

/// T as PCL's homogeneous matrix (a rotation about z; z is left alone).
Eigen::Matrix4f ToMatrix(const geometry::Pose2& T) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.topLeftCorner<2, 2>() = T.rotation().cast<float>();
  m(0, 3) = static_cast<float>(T.x);
  m(1, 3) = static_cast<float>(T.y);
  return m;
}

geometry::Pose2 ToPose(const Eigen::Matrix4f& m) {
  return {m(0, 3), m(1, 3), std::atan2(m(1, 0), m(0, 0))};
}

/// Scores `match` at T_shelf_lidar: each source point's distance d to the (nearest template point
/// of the) outline; the fitness is the mean of min(d, inlier distance)^2, the inliers give the
/// RMS and the legs seen. Accepted: converged, enough legs, a small enough RMS.
void ScoreMatch(const Cloud& source, const Tree& tree, const std::vector<OutlinePoint>& outline,
                const geometry::Pose2& T_shelf_lidar, const IcpPeerConfig& config,
                IcpMatch* match) {
  const double c2 = config.inlier_distance_m * config.inlier_distance_m;
  std::array<int, 4> leg_points = {0, 0, 0, 0};
  double inlier_sq = 0.0, fitness = 0.0;
  pcl::Indices nearest(1);
  std::vector<float> sq(1);
  for (const Point& p : source.points) {
    const Eigen::Vector2d q = T_shelf_lidar * Eigen::Vector2d(p.x, p.y);
    tree.nearestKSearch(ToPoint(q), 1, nearest, sq);
    const double d2 = sq[0];
    fitness += std::min(d2, c2);
    if (d2 > c2) continue;
    ++match->inliers;
    inlier_sq += d2;
    ++leg_points[outline[nearest[0]].leg];
  }
  match->fitness = fitness / static_cast<double>(source.size());
  match->inlier_rms_m = match->inliers > 0 ? std::sqrt(inlier_sq / match->inliers)
                                           : std::numeric_limits<double>::infinity();
  match->legs = static_cast<int>(std::count_if(leg_points.begin(), leg_points.end(),
                                               [&](int n) { return n >= config.min_leg_points; }));
  match->accepted = match->converged && match->legs >= config.min_legs &&
                    match->inlier_rms_m <= config.max_inlier_rms_m;
}

}  // namespace

std::vector<OutlinePoint> LegOutline(const geometry::ShelfModel& model, double step_m) {
  std::vector<OutlinePoint> out;
  const geometry::LegModel& leg = model.leg;
  const std::array<Eigen::Vector2d, 4> centres = model.LegCentres();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d& c = centres[k];
    if (leg.shape == geometry::LegShape::kCircle) {
      const double r = leg.Radius();
      const int n = std::max(8, static_cast<int>(std::ceil(2.0 * std::numbers::pi * r / step_m)));
      for (int i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n;
        const Eigen::Vector2d u(std::cos(a), std::sin(a));
        out.push_back({c + r * u, u, k});
      }
      continue;
    }
    // The rectangle's corners counter-clockwise; each side from its corner (whose normal is the
    // diagonal: it belongs to both sides), without the next corner.
    const double hx = 0.5 * leg.length_m, hy = 0.5 * leg.width_m;
    const std::array<Eigen::Vector2d, 4> corners = {
        Eigen::Vector2d(-hx, -hy), Eigen::Vector2d(hx, -hy), Eigen::Vector2d(hx, hy),
        Eigen::Vector2d(-hx, hy)};
    for (int s = 0; s < 4; ++s) {
      const Eigen::Vector2d& a = corners[s];
      const Eigen::Vector2d& b = corners[(s + 1) % 4];
      const Eigen::Vector2d side_normal = Eigen::Vector2d((b - a).y(), -(b - a).x()).normalized();
      const int n = std::max(1, static_cast<int>(std::round((b - a).norm() / step_m)));
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector2d normal = i == 0 ? Eigen::Vector2d(a.normalized()) : side_normal;
        out.push_back({c + a + (b - a) * (static_cast<double>(i) / n), normal, k});
      }
    }
  }
  return out;
}

std::vector<OutlinePoint> FacingSensor(const std::vector<OutlinePoint>& outline,
                                       const Eigen::Vector2d& p_shelf_sensor) {
  std::vector<OutlinePoint> out;
  for (const OutlinePoint& o : outline) {
    if (o.normal.dot(p_shelf_sensor - o.p_shelf) > 0.0) out.push_back(o);
  }
  return out;
}

IcpPeer::IcpPeer(const std::vector<geometry::ShelfModel>& models,
                 const perception::DetectorConfig& detector, const IcpPeerConfig& config)
    : models_(models), detector_(detector), config_(config) {
  // PCL reports "not enough correspondences" on its console; here that is an expected failure,
  // returned as a value, and the core does not print.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  for (const geometry::ShelfModel& model : models_) {
    outlines_.push_back(LegOutline(model, config_.outline_step_m));
  }
}

std::vector<IcpMatch> IcpPeer::Match(const geometry::LaserScan& scan,
                                     const std::optional<geometry::Pose2>& T_lidar_preset) const {
  if (!T_lidar_preset || models_.empty()) return {};
  // The source: the scan points in the detector's region of interest (same radius as
  // perception::Preprocess, so every model sees the same points).
  double longest_diagonal = 0.0;
  for (const auto& m : models_) longest_diagonal = std::max(longest_diagonal, m.Diagonal());
  const double roi_radius = detector_.preprocess.roi_gamma * longest_diagonal;
  auto source = std::make_shared<Cloud>();
  for (const perception::ScanPoint& p : perception::ScanToPoints(scan)) {
    if ((p.p - T_lidar_preset->translation()).norm() <= roi_radius) source->push_back(ToPoint(p.p));
  }
  if (source->size() < 3) return {};

  std::vector<IcpMatch> matches;
  const Eigen::Vector2d p_shelf_sensor = T_lidar_preset->inverse().translation();
  for (int m = 0; m < static_cast<int>(models_.size()); ++m) {
    // The target and its k-d tree, shared by ICP and the scoring below.
    const std::vector<OutlinePoint> outline =
        config_.facing_sides_only ? FacingSensor(outlines_[m], p_shelf_sensor) : outlines_[m];
    auto target = std::make_shared<Cloud>();
    for (const OutlinePoint& o : outline) target->push_back(ToPoint(o.p_shelf));
    auto tree = std::make_shared<Tree>();
    tree->setInputCloud(target);

    Icp icp;
    icp.setTransformationEstimation(
        std::make_shared<pcl::registration::TransformationEstimation2D<Point, Point>>());
    icp.setInputSource(source);
    icp.setInputTarget(target);
    icp.setSearchMethodTarget(tree, /*force_no_recompute=*/true);
    icp.setMaximumIterations(config_.max_iterations);
    icp.setTransformationEpsilon(config_.transformation_epsilon);

    // ICP moves the source onto the target: its transform is T_shelf_lidar.
    Eigen::Matrix4f T_shelf_lidar = ToMatrix(T_lidar_preset->inverse());
    IcpMatch match;
    match.model = m;
    Cloud aligned;
    for (double max_pair_m : config_.correspondence_schedule_m) {
      icp.setMaxCorrespondenceDistance(max_pair_m);
      icp.align(aligned, T_shelf_lidar);
      match.iterations += icp.Iterations();
      if (!icp.hasConverged()) break;
      T_shelf_lidar = icp.getFinalTransformation();
    }
    match.converged = icp.hasConverged();
    match.T_lidar_shelf = ToPose(T_shelf_lidar).inverse();

    ScoreMatch(*source, *tree, outline, ToPose(T_shelf_lidar), config_, &match);
    matches.push_back(match);
  }
  return matches;
}

std::optional<PeerEstimate> IcpPeer::Detect(
    const geometry::LaserScan& scan, const std::optional<geometry::Pose2>& T_lidar_preset) const {
  const IcpMatch* best = nullptr;
  const std::vector<IcpMatch> matches = Match(scan, T_lidar_preset);
  for (const IcpMatch& m : matches) {
    if (m.accepted && (best == nullptr || m.fitness < best->fitness)) best = &m;
  }
  if (best == nullptr) return std::nullopt;
  const geometry::ShelfModel& model = models_[best->model];
  geometry::Pose2 T_lidar_shelf = best->T_lidar_shelf;
  T_lidar_shelf.yaw =
      ResolvePeerHeading(T_lidar_shelf.yaw, T_lidar_shelf, T_lidar_preset, model.HeadingPeriod());
  return PeerEstimate{model.name, T_lidar_shelf, best->legs};
}

}  // namespace shelfdock::eval::peers
