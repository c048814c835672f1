#pragma once

// The ICP peer needs PCL: this header does not include it, and its source is built only with
// the CMake option SHELFDOCK_WITH_PCL (library shelfdock_icp_peer).

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "eval/peers/peer_estimate.hpp"
#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"

namespace shelfdock::eval::peers {

/// Settings of the ICP peer. ICP runs in stages from the preset, each starting where the last
/// one ended, with a shrinking pairing distance: the first covers the preset's error, the last
/// pairs only points on the legs. On the rows of `eval peers --quick`, where a rack or a
/// neighbouring shelf can pull the template off, 0.3 m alone found 9 of 20 targets, 0.3 -> 0.05 m
/// 11 and 0.3 -> 0.1 -> 0.05 m 17.
struct IcpPeerConfig {
  double outline_step_m = 0.01;  ///< [m] template points along each leg's perimeter
  /// Template: only the leg sides that face the sensor at the preset pose. With the full
  /// perimeters a leg's back side, 4 cm behind its front, holds front-side points in a local
  /// minimum (shelf 2 from presets up to 0.15 m off: median centre error 12 mm, against 3 mm)
  bool facing_sides_only = true;
  /// [m] each stage's largest point-template pair distance. The first: a preset 0.2 m and
  /// 0.1 rad off (the scene sets' worst) moves a leg 0.9 m from the centre by up to 0.29 m; the
  /// last: 5 sigma of the WLR-716's range noise
  std::vector<double> correspondence_schedule_m = {0.3, 0.1, 0.05};
  int max_iterations = 30;  ///< [-] per stage (a stage stops earlier once its pairs stop moving)
  /// [m^2] PCL's stop test: an iteration's squared translation (and 1 - cos of its rotation)
  double transformation_epsilon = 1e-8;
  double inlier_distance_m = 0.03;  ///< [m] a scan point this close to the outline fits it
  /// [-] fitting points that make a leg seen: one, since a 26 mm round leg at 3.5 m catches one
  /// or two beams
  int min_leg_points = 1;
  int min_legs = 3;                 ///< [-] fewer legs seen: no shelf (as the other methods)
  double max_inlier_rms_m = 0.015;  ///< [m] worse fitting points: no shelf
};

/// One model's ICP result on one scan.
struct IcpMatch {
  int model = -1;  ///< index in the models
  geometry::Pose2 T_lidar_shelf;
  bool converged = false;     ///< PCL's verdict after the last stage
  int iterations = 0;         ///< [-] all stages
  int inliers = 0;            ///< [-] scan points within inlier_distance_m of the outline
  int legs = 0;               ///< [-] legs with at least min_leg_points inliers
  double inlier_rms_m = 0.0;  ///< [m] over the inliers
  /// [m^2] mean over the region's points of min(d, inlier_distance_m)^2, d the distance to the
  /// outline: the same points for every model, so the models compare on it (lower is better)
  double fitness = 0.0;
  bool accepted = false;  ///< converged, min_legs legs seen, inlier_rms_m small enough
};

/// A template point: on a leg's perimeter, in the shelf frame.
struct OutlinePoint {
  Eigen::Vector2d p_shelf = Eigen::Vector2d::Zero();  ///< [m]
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  ///< outward unit normal (corners: diagonal)
  int leg = 0;                                        ///< index in ShelfModel::LegCentres()
};

/// Every leg's perimeter (rectangle or circle) in the shelf frame, a point about every `step_m`.
std::vector<OutlinePoint> LegOutline(const geometry::ShelfModel& model, double step_m);

/// The points of `outline` on the sides that face a sensor at `p_shelf_sensor` (outward normal
/// toward it): what a scan can hit, occlusion by other legs aside.
std::vector<OutlinePoint> FacingSensor(const std::vector<OutlinePoint>& outline,
                                       const Eigen::Vector2d& p_shelf_sensor);

/// Peer "ICP template matching" with PCL, the point-cloud matching the paper's related work
/// names: pcl::IterativeClosestPoint with a 2D transformation estimation (x, y, yaw) that
/// aligns the scan points in the detector's region of interest around the preset (source) with
/// a model's leg outline (target: the leg sides facing the sensor at the preset, in the shelf
/// frame), started from the preset. Every model is tried (the peers get the models shelfdock
/// gets, not the target's); the accepted match with the lowest fitness wins. Without a preset
/// there is nothing to start from: nullopt, as when no model is accepted.
class IcpPeer {
 public:
  IcpPeer(const std::vector<geometry::ShelfModel>& models,
          const perception::DetectorConfig& detector, const IcpPeerConfig& config = {});

  /// Every model's match, in the models' order (empty without a preset or scan points).
  std::vector<IcpMatch> Match(const geometry::LaserScan& scan,
                              const std::optional<geometry::Pose2>& T_lidar_preset) const;

  /// The best accepted match as the peers answer, its heading resolved as theirs.
  std::optional<PeerEstimate> Detect(const geometry::LaserScan& scan,
                                     const std::optional<geometry::Pose2>& T_lidar_preset) const;

 private:
  std::vector<geometry::ShelfModel> models_;
  perception::DetectorConfig detector_;
  IcpPeerConfig config_;
  std::vector<std::vector<OutlinePoint>> outlines_;  ///< per model, built once
};

}  // namespace shelfdock::eval::peers
