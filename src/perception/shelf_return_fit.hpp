#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"
#include "perception/leg_fit.hpp"
#include "perception/mixed_returns.hpp"
#include "perception/scan_point.hpp"
#include "perception/shelf_fit.hpp"

namespace shelfdock::perception {

/// One leg of a shelf as the scan shows it, for the fit on the returns.
struct LegReturns {
  int corner = -1;  ///< model corner (ShelfModel::LegCentres) the leg stands at
  /// Its returns (beam order) and outline; empty for a leg seen only blended with its
  /// background, which counts through `centre` instead.
  const std::vector<ScanPoint>* points = nullptr;
  SilhouetteTerm silhouette;
  double range_sigma_m = 0.01;  ///< [m] std of one return's range on this leg
  /// Its outer returns that may be blends with the surface beyond (none by default).
  MixedEdges mixed;
  /// [rad] Half the angle by which the beams' spots draw the leg wider than it stands (half the
  /// bloom granted to the set's legs): a return whose beam passes the leg by less than this
  /// times its range came from the part of the leg its spot reached (ReturnRayResidual).
  double spot_half_rad = 0.0;
  /// A blended leg: where it stands and how well that is known along / across its beam.
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  LegSigma centre_sigma;
};

/// The shelf pose fitted to the legs' returns themselves rather than to the fitted leg centres.
struct ShelfReturnFitResult {
  geometry::Pose2 T_lidar_shelf;  ///< heading wrapped to [-pi, pi)
  double chi2 = 0.0;  ///< sum of the squared residuals over their std (robust weights applied)
  int residuals = 0;  ///< how many terms the chi-square sums
};

/// Refines a shelf pose (x, y, yaw) on its legs' returns: every return is ray-cast against its
/// leg's section placed by the model at its corner and turned with the shelf (legs are mounted
/// square to the frame), and every leg's outline bearing is held as in FitLeg. Fitting each leg
/// alone and then the shelf to the leg centres lets a far leg of one or two returns wander along
/// its face (where on the section those returns hit is not known), which the leg's range then
/// follows; here the other legs fix it. Huber weights by iteratively reweighted least squares
/// (LegFitConfig::loss_scale_m), Ceres' TinySolver from `T_init`. The chi-square compares the
/// models of one leg set on the same returns. A leg whose corner is not 0-3: `T_init` and an
/// infinite chi-square.
ShelfReturnFitResult FitShelfToReturns(const std::vector<LegReturns>& legs,
                                       const geometry::ShelfModel& model,
                                       const geometry::Pose2& T_init, const LegFitConfig& config);

}  // namespace shelfdock::perception
