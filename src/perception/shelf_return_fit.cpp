#include "perception/shelf_return_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <ceres/tiny_solver.h>
#include <ceres/tiny_solver_autodiff_function.h>

#include "geometry/angle.hpp"
#include "perception/leg_fit.hpp"
#include "perception/leg_ray_residual.hpp"
#include "perception/leg_silhouette.hpp"
#include "perception/mixed_returns.hpp"

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

  // Where leg l's section is centred under the pose x, whose heading has cosine c and sine s.
  template <typename T>
  void LegCentre(const T* x, const T& c, const T& s, std::size_t l, T* centre) const {
    const Eigen::Vector2d& u = corners[static_cast<std::size_t>((*legs)[l].corner)];
    centre[0] = x[0] + c * T(u.x()) - s * T(u.y());
    centre[1] = x[1] + s * T(u.x()) + c * T(u.y());
  }

  // Return q's residuals (range, miss distance) in metres against a section at `centre`, turned
  // with the shelf, seen through a spot `spot_half_rad` wide on each side of its beam.
  template <typename T>
  void ReturnResidual(const T* centre, const T& c, const T& s, const ScanPoint& q,
                      double spot_half_rad, T* r) const {
    ReturnRayResidual(centre, q, round, radius, c, s, half_x, half_y, r, spot_half_rad * q.range);
  }

  // Leg l's outline bearing error [rad] (its silhouette term, unweighted).
  template <typename T>
  T OutlineError(const T* centre, const T& c, const T& s, std::size_t l) const {
    const SilhouetteTerm& sil = (*legs)[l].silhouette;
    const Eigen::Vector2d& mid = (*mid_directions)[l];
    return SilhouetteBearingError(centre, round, radius, c, s, half_x, half_y, mid.x(), mid.y(),
                                  sil.edge_side, sil.edge_rad);
  }

  template <typename T>
  bool operator()(const T* x, T* residual) const {
    using std::cos;
    using std::sin;
    const T c = cos(x[2]);
    const T s = sin(x[2]);
    int k = 0;
    for (std::size_t l = 0; l < legs->size(); ++l) {
      const LegReturns& leg = (*legs)[l];
      T centre[2];
      LegCentre(x, c, s, l, centre);
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
        T* r = residual + k;
        ReturnResidual(centre, c, s, (*leg.points)[i], leg.spot_half_rad, r);
        r[0] *= T(w[i] * inv_sigma);
        r[1] *= T(w[i] * inv_sigma);
        k += 2;
      }
      const SilhouetteTerm& sil = leg.silhouette;
      residual[k++] = sil.sigma_rad > 0.0 ? T((*silhouette_weights)[l] / sil.sigma_rad) *
                                                OutlineError(centre, c, s, l)
                                          : T(0);
    }
    return true;
  }
};

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
  const auto corners = model.LegCentres();
  ShelfReturnCost cost{&legs,
                       &weights,
                       &silhouette_weights,
                       &mid_directions,
                       {corners[0], corners[1], corners[2], corners[3]},
                       model.leg.shape == geometry::LegShape::kCircle,
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
      double centre[2];
      cost.LegCentre(x.data(), c, s, l, centre);
      for (std::size_t i = 0; i < leg.points->size(); ++i) {
        double r[2];
        cost.ReturnResidual(centre, c, s, (*leg.points)[i], leg.spot_half_rad, r);
        weights[l][i] = HuberSqrtWeight(std::hypot(r[0], r[1]), config.loss_scale_m);
        // As FitLeg: an outer return that may be a blend keeps its range as far as the noise
        // explains it.
        weights[l][i] = std::min(
            weights[l][i],
            MixedReturnSqrtWeight(r[0], MixedEdgeNoise(leg.range_sigma_m, config),
                                  leg.mixed.Gap(i, leg.points->size()), config.mixed_edge_share));
      }
      const SilhouetteTerm& sil = leg.silhouette;
      if (sil.sigma_rad > 0.0) {
        const double e = cost.OutlineError(centre, c, s, l);
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
