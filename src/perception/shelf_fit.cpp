#include "perception/shelf_fit.hpp"

#include <cmath>
#include <numbers>

#include <ceres/tiny_solver.h>
#include <ceres/tiny_solver_autodiff_function.h>
#include <Eigen/Dense>

#include "geometry/angle.hpp"
#include "perception/model_match.hpp"

namespace shelfdock::perception {
namespace {

// The unit direction of the beam to `leg` (x for a leg at the sensor).
Eigen::Vector2d BeamDirection(const Eigen::Vector2d& leg) {
  const double norm = leg.norm();
  return norm > 1e-9 ? Eigen::Vector2d(leg / norm) : Eigen::Vector2d::UnitX();
}

// Rows: the error along and across the leg's beam, times `w_along` and `w_across` (one over
// their std).
Eigen::Matrix2d BeamWeights(const Eigen::Vector2d& leg, double w_along, double w_across) {
  const Eigen::Vector2d along = BeamDirection(leg);
  Eigen::Matrix2d a;
  a << w_along * along.x(), w_along * along.y(), -w_across * along.y(), w_across * along.x();
  return a;
}

// Rows: the error along and across the leg's beam, each over its std.
Eigen::Matrix2d InfoSqrt(const Eigen::Vector2d& leg, const LegSigma& sigma) {
  return BeamWeights(leg, 1.0 / sigma.along_m, 1.0 / sigma.across_m);
}

// `cost` (kResiduals residuals of kParams parameters) minimised from `x` by Ceres' TinySolver:
// dense Levenberg-Marquardt with automatic differentiation and no heap allocation, at most
// `max_iterations` iterations. False when it stopped on that cap rather than on a small gradient,
// step, cost or cost change.
template <int kResiduals, int kParams, typename Cost>
bool SolveTiny(const Cost& cost, Eigen::Matrix<double, kParams, 1>& x, int max_iterations) {
  using AutoDiff = ceres::TinySolverAutoDiffFunction<Cost, kResiduals, kParams>;
  ceres::TinySolver<AutoDiff> solver;
  solver.options.max_num_iterations = max_iterations;
  const AutoDiff function(cost);
  return solver.Solve(function, &x).status != ceres::TinySolver<AutoDiff>::HIT_MAX_ITERATIONS;
}

// TinySolver's own iteration cap, for the solves that set none.
constexpr int kTinySolverIterations = 50;

// Leg (lx, ly) against model corner k at the pose x = (x, y, yaw) (c, s: its cos and sin): the
// error along and across the leg's beam over their std (A), into r[0], r[1].
template <typename T>
void LegResidual(const T& lx, const T& ly, const Eigen::Vector2d& k, const Eigen::Matrix2d& A,
                 const T* x, const T& c, const T& s, T* r) {
  const T ex = lx - (x[0] + c * T(k.x()) - s * T(k.y()));
  const T ey = ly - (x[1] + s * T(k.x()) + c * T(k.y()));
  r[0] = T(A(0, 0)) * ex + T(A(0, 1)) * ey;
  r[1] = T(A(1, 0)) * ex + T(A(1, 1)) * ey;
}

// Eq. 8-10 for all legs: u_i = (c_x, c_y) + R(c_alpha) (s_x L/2, s_y W/2) is the model corner
// leg i belongs to (Eq. 8-9 is the corner with s = (-1, -1)); residual_i = leg_i - u_i.
// Eq. 10 sums |dx| + |dy|: that is not rotation invariant, not differentiable at the optimum
// and not what the "nonlinear least squares" of Eq. 11 solves. We use the squared Euclidean
// distance (the maximum-likelihood choice for isotropic Gaussian leg errors), made robust to a
// wrong leg by Cauchy weights applied as iteratively reweighted least squares (the residuals
// are scaled by sqrt(w_i)). Unused legs (3-leg sets) have zero weight.
// Each residual is split along and across the leg's beam and divided by its std there (a
// deviation from the paper's equal weights): a fitted leg centre is known to a fraction of a
// beam step across the beam (its silhouette) but only to range noise / sqrt(beams on the leg)
// along it, so equal weights let the range noise of the far legs into the heading.
struct CornerCost {
  // Zeroed: a 3-leg set leaves slot 3 unset, and its residual is 0 * (A * e) only while e is
  // finite (Eigen leaves vectors uninitialised; stack garbage there made the sanitizer build's
  // fits fail now and then with NaN residuals).
  std::array<Eigen::Vector2d, 4> legs{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                      Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  std::array<Eigen::Vector2d, 4> corners{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                         Eigen::Vector2d::Zero(),
                                         Eigen::Vector2d::Zero()};  // shelf frame
  std::array<double, 4> sqrt_w{0.0, 0.0, 0.0, 0.0};
  // Rows: (along, across the leg's beam) / their std.
  std::array<Eigen::Matrix2d, 4> info_sqrt{Eigen::Matrix2d::Identity(), Eigen::Matrix2d::Identity(),
                                           Eigen::Matrix2d::Identity(),
                                           Eigen::Matrix2d::Identity()};
  template <typename T>
  bool operator()(const T* x, T* residual) const {
    using std::cos;
    using std::sin;
    const T c = cos(x[2]);
    const T s = sin(x[2]);
    for (int i = 0; i < 4; ++i) {
      T r[2];
      LegResidual(T(legs[i].x()), T(legs[i].y()), corners[i], info_sqrt[i], x, c, s, r);
      residual[2 * i] = T(sqrt_w[i]) * r[0];
      residual[2 * i + 1] = T(sqrt_w[i]) * r[1];
    }
    return true;
  }
};

}  // namespace

std::optional<ShelfFitResult> FitShelf(const std::array<Eigen::Vector2d, 4>& legs, int count,
                                       const geometry::ShelfModel& model,
                                       const ShelfFitConfig& config) {
  if (count != 3 && count != 4) return std::nullopt;
  const EdgeSizes edges = MeasureEdges(legs, count);
  const Eigen::Vector2d long_edge = edges.first_edge_long ? Eigen::Vector2d(legs[1] - legs[0])
                                                          : Eigen::Vector2d(legs[2] - legs[1]);
  // The paper starts from the legs' mean; with 3 legs the hypotenuse midpoint is the centre.
  const Eigen::Vector2d start =
      count == 4 ? Eigen::Vector2d(0.25 * (legs[0] + legs[1] + legs[2] + legs[3]))
                 : Eigen::Vector2d(0.5 * (legs[0] + legs[2]));
  const geometry::Pose2 T_init(start.x(), start.y(), std::atan2(long_edge.y(), long_edge.x()));

  // Pair each leg with the nearest model corner under the initial pose; must be one-to-one.
  const auto corners = model.LegCentres();
  std::array<Eigen::Vector2d, 4> placed;  // the corners under the initial pose
  for (int k = 0; k < 4; ++k) placed[k] = T_init * corners[k];
  std::array<int, 4> corner_of{-1, -1, -1, -1};
  std::array<bool, 4> taken{false, false, false, false};
  for (int i = 0; i < count; ++i) {
    int best = 0;
    for (int k = 1; k < 4; ++k) {
      if ((placed[k] - legs[i]).norm() < (placed[best] - legs[i]).norm()) best = k;
    }
    if (taken[best]) return std::nullopt;
    taken[best] = true;
    corner_of[i] = best;
  }

  CornerCost cost;
  for (int i = 0; i < count; ++i) {
    cost.legs[i] = legs[i];
    cost.corners[i] = corners[corner_of[i]];
    cost.sqrt_w[i] = 1.0;
    // The std along the beam grows as sqrt(range) (beams on a leg fall as 1 / range), across it
    // as range (a bearing); scaled so that a leg at 1 m weighs 1 along its beam, which keeps
    // the Cauchy scale in metres.
    const double range = std::max(legs[i].norm(), 0.1);
    cost.info_sqrt[i] =
        BeamWeights(legs[i], 1.0 / std::sqrt(range),
                    config.leg_radial_sigma_m / (config.leg_bearing_sigma_rad * range));
  }
  // 3 parameters and 8 residuals; the heading is wrapped to [-pi, pi) after the solve (the cost
  // is 2 pi periodic).
  Eigen::Vector3d x(T_init.x, T_init.y, T_init.yaw);
  constexpr int kIrlsRounds = 3;
  const double s2 = config.loss_scale_m * config.loss_scale_m;
  double robust_cost = 0.0;
  bool solver_converged = false;
  for (int round = 0; round < kIrlsRounds; ++round) {
    // Converged: the last round stopped on a small gradient, step, cost or cost change, not on
    // the iteration cap (with only 3 parameters LM needs a handful of iterations).
    solver_converged = SolveTiny<8, 3>(cost, x, config.max_iterations);
    // Cauchy: rho(e2) = s^2 log(1 + e2 / s^2), weight rho'(e2) = 1 / (1 + e2 / s^2).
    const geometry::Pose2 T(x(0), x(1), x(2));
    const Eigen::Matrix2d R = T.rotation();
    robust_cost = 0.0;
    for (int i = 0; i < count; ++i) {
      const double e2 = (legs[i] - (R * cost.corners[i] + T.translation())).squaredNorm();
      cost.sqrt_w[i] = std::sqrt(1.0 / (1.0 + e2 / s2));
      robust_cost += 0.5 * s2 * std::log1p(e2 / s2);
    }
  }
  const bool finite = x.allFinite();
  const bool converged = finite && solver_converged;
  const double yaw = geometry::WrapAngle(x(2));
  const double centre[2] = {x(0), x(1)};

  ShelfFitResult out;
  out.T_lidar_shelf = geometry::Pose2(centre[0], centre[1], yaw);
  out.cost = robust_cost;
  out.converged = converged;
  out.legs_used = count;
  out.corner_of_leg = corner_of;
  out.length_m = edges.long_m;
  out.width_m = edges.short_m;

  // Covariance: residual r_i = leg_i - (t + R c_i), so dr/dt = -I and dr/dyaw = -R' c_i.
  Eigen::Matrix<double, 8, 3> J = Eigen::Matrix<double, 8, 3>::Zero();
  double sum_sq = 0.0;
  const Eigen::Matrix2d R = out.T_lidar_shelf.rotation();
  Eigen::Matrix2d dR;
  dR << -R(1, 0), -R(0, 0), R(0, 0), -R(1, 0);  // d/dyaw of [c -s; s c]
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d& ci = corners[corner_of[i]];
    sum_sq += (legs[i] - (R * ci + out.T_lidar_shelf.translation())).squaredNorm();
    J.block<2, 2>(2 * i, 0) = -Eigen::Matrix2d::Identity();
    J.block<2, 1>(2 * i, 2) = -dR * ci;
  }
  out.rms_m = std::sqrt(sum_sq / count);
  const double dof = std::max(1, 2 * count - 3);
  const double variance = std::max(sum_sq / dof, config.min_leg_sigma_m * config.min_leg_sigma_m);
  out.covariance = variance * (J.transpose() * J).inverse();
  return out;
}

double LegsChiSquare(const std::array<Eigen::Vector2d, 4>& legs, int count,
                     const geometry::ShelfModel& model, const std::array<int, 4>& corner_of_leg,
                     const geometry::Pose2& T_lidar_shelf, const std::array<LegSigma, 4>& sigma) {
  const auto corners = model.LegCentres();
  double chi2 = 0.0;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d e = legs[i] - T_lidar_shelf * corners[corner_of_leg[i]];
    chi2 += (InfoSqrt(legs[i], sigma[i]) * e).squaredNorm();
  }
  return chi2;
}

namespace {
// The legs against the model when every range may read long by one unknown b, the sensor's
// systematic range error: residual_i = A_i (leg_i - b u_i - u(x, corner_i)) with u_i leg i's
// beam direction, and b / sigma_b as a prior on the bias (a zero-mean guess of that spread).
// From legs at one bearing b is a shift along the beams that the pose takes up; from legs all
// around the sensor (under a shelf) it is the shelf looking 2b larger than its model.
struct BiasedCornerCost {
  std::array<Eigen::Vector2d, 4> legs{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                      Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  std::array<Eigen::Vector2d, 4> corners{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                         Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  std::array<Eigen::Vector2d, 4> rays{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                      Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  std::array<Eigen::Matrix2d, 4> info_sqrt{Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero(),
                                           Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()};
  double inv_sigma_b = 0.0;
  template <typename T>
  bool operator()(const T* x, T* residual) const {
    using std::cos;
    using std::sin;
    const T c = cos(x[2]);
    const T s = sin(x[2]);
    for (int i = 0; i < 4; ++i) {
      LegResidual(T(legs[i].x()) - x[3] * T(rays[i].x()), T(legs[i].y()) - x[3] * T(rays[i].y()),
                  corners[i], info_sqrt[i], x, c, s, residual + 2 * i);
    }
    residual[8] = T(inv_sigma_b) * x[3];
    return true;
  }
};
}  // namespace

RangeBiasFit FitWithRangeBias(const std::array<Eigen::Vector2d, 4>& legs, int count,
                              const geometry::ShelfModel& model,
                              const std::array<int, 4>& corner_of_leg,
                              const geometry::Pose2& T_lidar_shelf,
                              const std::array<LegSigma, 4>& sigma, double bias_sigma_m) {
  const auto corners = model.LegCentres();
  BiasedCornerCost cost;  // unused legs keep zero weight
  for (int i = 0; i < count; ++i) {
    cost.legs[i] = legs[i];
    cost.corners[i] = corners[corner_of_leg[i]];
    cost.rays[i] = BeamDirection(legs[i]);
    cost.info_sqrt[i] = InfoSqrt(legs[i], sigma[i]);
  }
  cost.inv_sigma_b = 1.0 / bias_sigma_m;
  Eigen::Vector4d x(T_lidar_shelf.x, T_lidar_shelf.y, T_lidar_shelf.yaw, 0.0);
  SolveTiny<9, 4>(cost, x, kTinySolverIterations);
  RangeBiasFit out;
  if (!x.allFinite()) {  // the pose as given, no bias
    out.chi2 = LegsChiSquare(legs, count, model, corner_of_leg, T_lidar_shelf, sigma);
    return out;
  }
  Eigen::Matrix<double, 9, 1> r;
  cost(x.data(), r.data());
  out.chi2 = r.squaredNorm();
  out.bias_m = x(3);
  out.T_lidar_shelf = geometry::Pose2(x(0), x(1), geometry::WrapAngle(x(2)));
  return out;
}

ShelfRefineResult RefineShelfPose(const std::array<Eigen::Vector2d, 4>& legs, int count,
                                  const geometry::ShelfModel& model, const ShelfFitResult& fit,
                                  const std::array<LegSigma, 4>& sigma) {
  const auto corners = model.LegCentres();
  CornerCost cost;  // unused legs keep weight 0
  for (int i = 0; i < count; ++i) {
    cost.legs[i] = legs[i];
    cost.corners[i] = corners[fit.corner_of_leg[i]];
    cost.sqrt_w[i] = 1.0;
    cost.info_sqrt[i] = InfoSqrt(legs[i], sigma[i]);
  }
  Eigen::Vector3d x(fit.T_lidar_shelf.x, fit.T_lidar_shelf.y, fit.T_lidar_shelf.yaw);
  SolveTiny<8, 3>(cost, x, kTinySolverIterations);
  ShelfRefineResult out;
  if (!x.allFinite()) {  // keep the fit's pose; its chi-square as it stands
    x = Eigen::Vector3d(fit.T_lidar_shelf.x, fit.T_lidar_shelf.y, fit.T_lidar_shelf.yaw);
  }
  out.T_lidar_shelf = geometry::Pose2(x(0), x(1), geometry::WrapAngle(x(2)));
  out.chi2 = LegsChiSquare(legs, count, model, fit.corner_of_leg, out.T_lidar_shelf, sigma);
  return out;
}

}  // namespace shelfdock::perception
