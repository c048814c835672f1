#include "perception/shelf_return_fit.hpp"

#include <cmath>
#include <limits>

#include <ceres/tiny_solver.h>
#include <ceres/tiny_solver_autodiff_function.h>

#include "geometry/angle.hpp"
#include "perception/leg_ray_residual.hpp"
#include "perception/leg_silhouette.hpp"

namespace shelfdock::perception {
namespace {

// Per leg: 2 residuals per return (range, miss distance) and one silhouette bearing, or for a
// blended leg 2 on its assumed centre (along, across its beam). All in units of their std.
struct ShelfReturnCost {
  const std::vector<LegReturns>* legs;
  const std::vector<std::vector<double>>* weights;     // sqrt Huber weight per return
  const std::vector<double>* silhouette_weights;       // sqrt Huber weight per leg's silhouette
  const std::vector<Eigen::Vector2d>* mid_directions;  // (cos, sin) of each outline's mid_rad
  std::array<Eigen::Vector2d, 4> corners;              // shelf frame
  bool round;
  double radius, half_x, half_y;
  int n_residuals;

  int NumResiduals() const { return n_residuals; }

  template <typename T>
  bool operator()(const T* x, T* residual) const {
    using std::cos;
    using std::sin;
    const T c = cos(x[2]);
    const T s = sin(x[2]);
    int k = 0;
    for (std::size_t l = 0; l < legs->size(); ++l) {
      const LegReturns& leg = (*legs)[l];
      const Eigen::Vector2d& u = corners[static_cast<std::size_t>(leg.corner)];
      const T centre[2] = {x[0] + c * T(u.x()) - s * T(u.y()), x[1] + s * T(u.x()) + c * T(u.y())};
      if (leg.points == nullptr) {
        const double norm = leg.centre.norm();
        const Eigen::Vector2d along =
            norm > 1e-9 ? Eigen::Vector2d(leg.centre / norm) : Eigen::Vector2d::UnitX();
        const T ex = T(leg.centre.x()) - centre[0];
        const T ey = T(leg.centre.y()) - centre[1];
        residual[k++] = (T(along.x()) * ex + T(along.y()) * ey) / T(leg.centre_sigma.along_m);
        residual[k++] = (T(along.x()) * ey - T(along.y()) * ex) / T(leg.centre_sigma.across_m);
        continue;
      }
      const std::vector<double>& w = (*weights)[l];
      const double inv_sigma = 1.0 / leg.range_sigma_m;
      for (std::size_t i = 0; i < leg.points->size(); ++i) {
        const ScanPoint& q = (*leg.points)[i];
        const double ux = q.p.x() / q.range, uy = q.p.y() / q.range;
        T* r = residual + k;
        if (round) {
          CircleRayResidual(centre, ux, uy, q.range, radius, r);
        } else {
          BoxRayResidual(centre, ux, uy, q.range, c, s, half_x, half_y, r);
        }
        r[0] *= T(w[i] * inv_sigma);
        r[1] *= T(w[i] * inv_sigma);
        k += 2;
      }
      const SilhouetteTerm& sil = leg.silhouette;
      if (sil.sigma_rad > 0.0) {
        const Eigen::Vector2d& mid = (*mid_directions)[l];
        residual[k] = T((*silhouette_weights)[l] / sil.sigma_rad) *
                      SilhouetteBearingError(centre, round, radius, c, s, half_x, half_y, mid.x(),
                                             mid.y(), sil.edge_side, sil.edge_rad);
      } else {
        residual[k] = T(0);
      }
      ++k;
    }
    return true;
  }
};

double HuberSqrtWeight(double abs_residual, double k) {
  return abs_residual <= k ? 1.0 : std::sqrt(k / abs_residual);
}

}  // namespace

ShelfReturnFitResult FitShelfToReturns(const std::vector<LegReturns>& legs,
                                       const geometry::ShelfModel& model,
                                       const geometry::Pose2& T_init, const LegFitConfig& config) {
  ShelfReturnFitResult out;
  out.T_lidar_shelf = T_init;
  for (const LegReturns& leg : legs) {
    if (leg.corner < 0 || leg.corner > 3) {  // no corner to place the leg at: no fit
      out.chi2 = std::numeric_limits<double>::infinity();
      return out;
    }
  }
  std::vector<std::vector<double>> weights(legs.size());
  std::vector<double> silhouette_weights(legs.size(), 1.0);
  std::vector<Eigen::Vector2d> mid_directions(legs.size());
  int n = 0;
  for (std::size_t l = 0; l < legs.size(); ++l) {
    mid_directions[l] = {std::cos(legs[l].silhouette.mid_rad),
                         std::sin(legs[l].silhouette.mid_rad)};
    if (legs[l].points == nullptr) {
      n += 2;
      continue;
    }
    weights[l].assign(legs[l].points->size(), 1.0);
    n += 2 * static_cast<int>(legs[l].points->size()) + 1;
  }
  const bool round = model.leg.shape == geometry::LegShape::kCircle;
  const auto corners = model.LegCentres();
  ShelfReturnCost cost{&legs,
                       &weights,
                       &silhouette_weights,
                       &mid_directions,
                       {corners[0], corners[1], corners[2], corners[3]},
                       round,
                       model.leg.Radius(),
                       0.5 * model.leg.length_m,
                       0.5 * model.leg.width_m,
                       n};
  using AutoDiff = ceres::TinySolverAutoDiffFunction<ShelfReturnCost, Eigen::Dynamic, 3>;
  const AutoDiff function(cost);
  ceres::TinySolver<AutoDiff> solver;
  solver.options.max_num_iterations = config.max_iterations;
  // Stop when the chi-square changes by less than 0.1 % or the pose by micrometres: the start
  // (the legs' fit) is close, and the chi-square need not be known finer to choose a model.
  solver.options.function_tolerance = 1e-3;
  solver.options.parameter_tolerance = 1e-6;
  Eigen::Vector3d x(T_init.x, T_init.y, T_init.yaw);
  // One solve with plain weights, one with the Huber weights of its residuals.
  constexpr int kIrlsRounds = 2;
  for (int round_i = 0; round_i < kIrlsRounds; ++round_i) {
    solver.Solve(function, &x);
    if (!x.allFinite()) {
      x = Eigen::Vector3d(T_init.x, T_init.y, T_init.yaw);
      break;
    }
    if (round_i + 1 == kIrlsRounds) break;
    // The same robust loss as the leg fit, on the residuals in metres (radians for the outline).
    const double c = std::cos(x(2)), s = std::sin(x(2));
    for (std::size_t l = 0; l < legs.size(); ++l) {
      const LegReturns& leg = legs[l];
      if (leg.points == nullptr) continue;
      const Eigen::Vector2d& u = corners[static_cast<std::size_t>(leg.corner)];
      const double centre[2] = {x(0) + c * u.x() - s * u.y(), x(1) + s * u.x() + c * u.y()};
      for (std::size_t i = 0; i < leg.points->size(); ++i) {
        const ScanPoint& q = (*leg.points)[i];
        double r[2];
        if (round) {
          CircleRayResidual(centre, q.p.x() / q.range, q.p.y() / q.range, q.range,
                            model.leg.Radius(), r);
        } else {
          BoxRayResidual<double>(centre, q.p.x() / q.range, q.p.y() / q.range, q.range, c, s,
                                 cost.half_x, cost.half_y, r);
        }
        weights[l][i] = HuberSqrtWeight(std::hypot(r[0], r[1]), config.loss_scale_m);
      }
      const SilhouetteTerm& sil = leg.silhouette;
      if (sil.sigma_rad > 0.0) {
        const double e = SilhouetteBearingError(centre, round, model.leg.Radius(), c, s,
                                                cost.half_x, cost.half_y, mid_directions[l].x(),
                                                mid_directions[l].y(), sil.edge_side, sil.edge_rad);
        // As FitLeg: the Huber scale in metres, the bearing error weighed as a range.
        silhouette_weights[l] = HuberSqrtWeight(std::abs(config.range_sigma_m * e / sil.sigma_rad),
                                                config.loss_scale_m);
      }
    }
  }
  out.T_lidar_shelf = geometry::Pose2(x(0), x(1), geometry::WrapAngle(x(2)));
  Eigen::VectorXd r(n);
  function(x.data(), r.data(), nullptr);
  out.chi2 = r.squaredNorm();
  out.residuals = n;
  return out;
}

}  // namespace shelfdock::perception
