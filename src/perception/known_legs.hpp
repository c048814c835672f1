#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::perception {

/// Re-measuring a shelf whose pose is already known to a few millimetres from the legs the scan
/// shows where they are expected (MeasureKnownLegs).
struct KnownLegsConfig {
  double search_radius_m = 0.06;  ///< [m] points this near a predicted leg centre may be its points
  double gap_m = 0.05;            ///< [m] a leg's points: consecutive beams closer than this
  double size_margin_m = 0.02;    ///< [m] a run of points wider than the leg's extent plus this is
                                  ///< the leg merged with something touching it: not measured
  double max_offset_m = 0.03;     ///< [m] a fitted leg farther from its predicted centre: no result
  int min_points = 2;             ///< [-] fewer points: that leg is not measured
  double leg_sigma_m = 0.004;     ///< [m] std of one fitted leg centre (for the covariance)
  double max_rms_m = 0.012;       ///< [m] legs farther (RMS) from the fitted model: no result
  LegFitConfig leg_fit;           ///< the leg fit (paper 3.3) used on each leg's points
};

/// The shelf pose measured from known legs, in the lidar frame.
struct KnownLegsResult {
  geometry::Pose2 T_lidar_shelf;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< x [m], y [m], yaw [rad]
  int legs = 0;                                              ///< legs measured (>= 2)
  double rms_m = 0.0;  ///< [m] RMS distance of the fitted legs from the model's corners
};

/// Measures the shelf from two or more of its legs when its pose is already known well (a
/// tracked shelf): each corner marked in `use` is looked for within search_radius_m of where
/// `T_lidar_shelf_prior` puts it, its points are fitted as a leg (FitLeg), and the model's
/// corners are aligned to the fitted centres (least-squares rigid fit, closed form). The
/// detector needs three legs because it must find the shelf among everything else; with the
/// correspondence known, two legs (a known edge) fix position and heading. This is what lets
/// a robot keep measuring the shelf when only the two far legs are left in front of its LiDAR.
/// Empty when fewer than two legs are measured or they do not fit the model.
std::optional<KnownLegsResult> MeasureKnownLegs(const std::vector<ScanPoint>& points,
                                                const geometry::Pose2& T_lidar_shelf_prior,
                                                const geometry::ShelfModel& model,
                                                const std::array<bool, 4>& use,
                                                const KnownLegsConfig& config = {});

}  // namespace shelfdock::perception
