#pragma once

#include <array>
#include <optional>

#include <Eigen/Core>

#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"

namespace shelfdock::perception {

/// The shelf pose fitted to its leg centres (paper 3.4).
struct ShelfFitResult {
  geometry::Pose2 T_lidar_shelf;  ///< centre and heading (x along the long side; pi-ambiguous)
  double cost = 0.0;              ///< [m^2] final robustified cost, 0.5 sum rho(|r|^2)
  double rms_m = 0.0;             ///< [m] RMS distance of the legs from the fitted corners
  double length_m = 0.0;          ///< [m] mean long edge between the fitted leg centres
  double width_m = 0.0;           ///< [m] mean short edge between the fitted leg centres
  int legs_used = 0;              ///< 3 or 4
  std::array<int, 4> corner_of_leg{-1, -1, -1, -1};      ///< model corner (LegCentres) of each leg
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< of (x, y, yaw)
  bool converged = false;  ///< finite, and the solver stopped on its tolerances, not its cap
};

/// Paper 3.4: the shelf pose C = (c_x, c_y, c_alpha) from 3 or 4 fitted leg centres (cyclic
/// order as in LegSet; legs[3] unused when count == 3). Each leg is paired with the model corner
/// u = C (+-L/2, +-W/2) of Eq. 8-9 nearest to it under the initial pose (the legs' mean, or the
/// hypotenuse midpoint for 3 legs, and the direction of a long edge), then Ceres' TinySolver
/// minimises sum rho(|W_i (leg - u)|^2) with a Cauchy loss applied as IRLS weights (3 rounds);
/// W_i weighs the error along and across leg i's beam by its std there (leg_radial_sigma_m,
/// leg_bearing_sigma_rad). The heading is wrapped to [-pi, pi) afterwards. The covariance is (J^T
/// J)^-1 of the unweighted final Jacobian scaled by the residual variance (floored by
/// min_leg_sigma_m). nullopt when the legs cannot be paired one-to-one with corners.
std::optional<ShelfFitResult> FitShelf(const std::array<Eigen::Vector2d, 4>& legs, int count,
                                       const geometry::ShelfModel& model,
                                       const ShelfFitConfig& config);

/// The std of one fitted leg centre along its beam and across it [m].
struct LegSigma {
  double along_m = 0.01;
  double across_m = 0.01;
};

/// A shelf pose weighed by each leg's own measurement, and how well the legs fit it.
struct ShelfRefineResult {
  geometry::Pose2 T_lidar_shelf;  ///< heading wrapped to [-pi, pi)
  double chi2 = 0.0;  ///< sum over legs of (error along / along_m)^2 + (error across / across_m)^2
};

/// The chi-square of `count` legs against their model corners (`corner_of_leg` into
/// model.LegCentres()) at T_lidar_shelf: each leg's error split along and across its beam and
/// divided by sigma[i] (ShelfRefineResult::chi2).
double LegsChiSquare(const std::array<Eigen::Vector2d, 4>& legs, int count,
                     const geometry::ShelfModel& model, const std::array<int, 4>& corner_of_leg,
                     const geometry::Pose2& T_lidar_shelf, const std::array<LegSigma, 4>& sigma);

/// The legs' best fit to the model when every range may read long by one unknown bias.
struct RangeBiasFit {
  geometry::Pose2 T_lidar_shelf;
  double bias_m = 0.0;  ///< [m] what the ranges read too long by
  double chi2 = 0.0;    ///< LegsChiSquare of the legs moved back by the bias, plus (bias/sigma)^2
};

/// Fits the pose and a range bias shared by every leg (its prior zero-mean with std
/// bias_sigma_m > 0) from T_lidar_shelf and no bias: legs all around the sensor look larger than
/// their model by twice a bias, legs at one bearing only shifted along it. Ceres' TinySolver.
RangeBiasFit FitWithRangeBias(const std::array<Eigen::Vector2d, 4>& legs, int count,
                              const geometry::ShelfModel& model,
                              const std::array<int, 4>& corner_of_leg,
                              const geometry::Pose2& T_lidar_shelf,
                              const std::array<LegSigma, 4>& sigma, double bias_sigma_m);

/// Refines `fit` (FitShelf's pose on the same legs, with its leg-to-corner pairing) to the pose
/// that minimises the chi-square of the legs against their model corners, leg i's error split
/// along and across its beam and divided by sigma[i]. FitShelf weighs the legs by range alone
/// and robustly (a wrong leg must not drag the pose); once the legs are known to be the shelf's,
/// what each leg's returns can tell (how many, how noisy, how wide a beam step) weighs them
/// better, and the chi-square at the minimum compares models of one leg set fairly. Plain least
/// squares with Ceres' TinySolver from fit's pose.
ShelfRefineResult RefineShelfPose(const std::array<Eigen::Vector2d, 4>& legs, int count,
                                  const geometry::ShelfModel& model, const ShelfFitResult& fit,
                                  const std::array<LegSigma, 4>& sigma);

}  // namespace shelfdock::perception
