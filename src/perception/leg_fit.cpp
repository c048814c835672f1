#include "perception/leg_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <ceres/tiny_solver.h>
#include <ceres/tiny_solver_autodiff_function.h>
#include <Eigen/Eigenvalues>

#include "geometry/angle.hpp"
#include "perception/leg_ray_residual.hpp"

namespace shelfdock::perception {
namespace {

struct LegRayCost {
  const std::vector<ScanPoint>* points;
  const double* weights;  // sqrt of the IRLS weight per point
  bool round;
  double radius, cos_a, sin_a, half_x, half_y;
  Eigen::Vector2d prior;
  double prior_weight;

  int NumResiduals() const { return 2 * static_cast<int>(points->size()) + 2; }

  template <typename T>
  bool operator()(const T* c, T* residual) const {
    const auto n = points->size();
    for (std::size_t i = 0; i < n; ++i) {
      const ScanPoint& q = (*points)[i];
      const double ux = std::cos(q.angle), uy = std::sin(q.angle);
      T* r = residual + 2 * i;
      if (round) {
        CircleRayResidual(c, ux, uy, q.range, radius, r);
      } else {
        BoxRayResidual(c, ux, uy, q.range, T(cos_a), T(sin_a), half_x, half_y, r);
      }
      r[0] *= T(weights[i]);
      r[1] *= T(weights[i]);
    }
    // Weak pull toward the start: one visible face fixes the centre only across the face (and
    // one point only along its beam), so along the face the bias-corrected centroid decides.
    residual[2 * n] = T(prior_weight) * (c[0] - T(prior.x()));
    residual[2 * n + 1] = T(prior_weight) * (c[1] - T(prior.y()));
    return true;
  }
};

}  // namespace

PcaDirection PrincipalDirection(const std::vector<ScanPoint>& points) {
  PcaDirection out;
  if (points.size() < 2) return out;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& q : points) mean += q.p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();  // Eq. 4
  for (const auto& q : points) scatter += (q.p - mean) * (q.p - mean).transpose();
  scatter /= static_cast<double>(points.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
  const Eigen::Vector2d main = eig.eigenvectors().col(1);  // eigenvalues ascending
  out.yaw = std::atan2(main.y(), main.x());
  out.anisotropy = eig.eigenvalues()(1) / std::max(eig.eigenvalues()(0), 1e-12);
  return out;
}

LegFitResult FitLeg(const std::vector<ScanPoint>& points, const geometry::LegModel& leg,
                    double axis_yaw_hint, const LegFitConfig& config) {
  LegFitResult out;
  if (points.empty()) return out;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const auto& q : points) centroid += q.p;
  centroid /= static_cast<double>(points.size());

  // Axis: the PCA main direction, taken modulo pi/2 next to the hint so that G_h stays along
  // the shelf's long side.
  out.axis_yaw = axis_yaw_hint;
  const PcaDirection pca = PrincipalDirection(points);
  if (static_cast<int>(points.size()) >= config.pca_min_points &&
      pca.anisotropy >= config.pca_min_anisotropy) {
    const double quarter = 0.5 * std::numbers::pi;
    const double d = geometry::AngleDiff(pca.yaw, axis_yaw_hint);
    out.axis_yaw = geometry::WrapAngle(axis_yaw_hint + d - quarter * std::round(d / quarter));
    out.axis_from_pca = true;
  }

  // Start behind the centroid: visible points lie on the near side of the leg. For a circle
  // sampled uniformly across its silhouette the centroid lies pi/4 r in front of the centre.
  const bool round = leg.shape == geometry::LegShape::kCircle;
  const double depth = round ? 0.8 * leg.Radius() : 0.85 * 0.25 * (leg.length_m + leg.width_m);
  const Eigen::Vector2d view =
      centroid.norm() > 1e-9 ? centroid.normalized() : Eigen::Vector2d::UnitX();
  const Eigen::Vector2d c0 = centroid + depth * view;

  // Robust loss by iteratively reweighted least squares (Huber weights w = min(1, k / |r|)),
  // with Ceres' TinySolver (dense LM on 2 parameters) per round: far less overhead than
  // ceres::Problem for a handful of residuals.
  std::vector<double> weights(points.size(), 1.0);
  LegRayCost cost{&points,
                  weights.data(),
                  round,
                  leg.Radius(),
                  std::cos(out.axis_yaw),
                  std::sin(out.axis_yaw),
                  0.5 * leg.length_m,
                  0.5 * leg.width_m,
                  c0,
                  config.prior_weight};
  using AutoDiff = ceres::TinySolverAutoDiffFunction<LegRayCost, Eigen::Dynamic, 2>;
  const AutoDiff function(cost);
  ceres::TinySolver<AutoDiff> solver;
  solver.options.max_num_iterations = config.max_iterations;
  Eigen::Vector2d c = c0;
  bool ok = true;
  constexpr int kIrlsRounds = 3;
  for (int round_i = 0; round_i < kIrlsRounds && ok; ++round_i) {
    solver.Solve(function, &c);
    ok = std::isfinite(c.x()) && std::isfinite(c.y());
    if (round_i + 1 == kIrlsRounds || !ok) break;
    for (std::size_t i = 0; i < points.size(); ++i) {
      double r[2];
      const ScanPoint& q = points[i];
      if (round) {
        CircleRayResidual(c.data(), std::cos(q.angle), std::sin(q.angle), q.range, leg.Radius(), r);
      } else {
        BoxRayResidual<double>(c.data(), std::cos(q.angle), std::sin(q.angle), q.range, cost.cos_a,
                               cost.sin_a, cost.half_x, cost.half_y, r);
      }
      const double norm = std::hypot(r[0], r[1]);
      weights[i] = norm <= config.loss_scale_m ? 1.0 : std::sqrt(config.loss_scale_m / norm);
    }
  }

  out.centre = c;
  out.converged = ok;
  double sum_sq = 0.0;
  for (const auto& q : points) {
    double r[2];
    if (round) {
      CircleRayResidual(c.data(), std::cos(q.angle), std::sin(q.angle), q.range, leg.Radius(), r);
    } else {
      BoxRayResidual<double>(c.data(), std::cos(q.angle), std::sin(q.angle), q.range, cost.cos_a,
                             cost.sin_a, cost.half_x, cost.half_y, r);
    }
    sum_sq += r[0] * r[0] + r[1] * r[1];
  }
  out.rms_m = std::sqrt(sum_sq / static_cast<double>(points.size()));
  return out;
}

}  // namespace shelfdock::perception
