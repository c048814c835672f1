#include "perception/leg_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <ceres/tiny_solver.h>
#include <ceres/tiny_solver_autodiff_function.h>
#include <Eigen/Eigenvalues>

#include "geometry/angle.hpp"
#include "perception/leg_ray_residual.hpp"
#include "perception/leg_silhouette.hpp"
#include "perception/mixed_returns.hpp"

namespace shelfdock::perception {
namespace {

struct LegRayCost {
  const std::vector<ScanPoint>* points;
  const double* weights;  // sqrt of the IRLS weight per point
  bool round;
  double radius, cos_a, sin_a, half_x, half_y;
  Eigen::Vector2d prior;
  double prior_weight;
  double mid_cos, mid_sin;   // bearing of the silhouette's centre (between the outer beams)
  double silhouette_weight;  // range sigma / bearing sigma of that centre; 0: unknown
  // Only one edge seen: the bearing of that edge relative to mid, and which side it bounds
  // (-1 the smaller bearing, +1 the larger); 0: the centre term above.
  int edge_side = 0;
  double edge_rad = 0.0;

  int NumResiduals() const { return 2 * static_cast<int>(points->size()) + 3; }

  template <typename T>
  bool operator()(const T* c, T* residual) const {
    const auto n = points->size();
    for (std::size_t i = 0; i < n; ++i) {
      T* r = residual + 2 * i;
      ReturnResidual(c, (*points)[i], r);
      r[0] *= T(weights[i]);
      r[1] *= T(weights[i]);
    }
    // Weak pull toward the start: one visible face fixes the centre only across the face (and
    // one point only along its beam); along the face the silhouette decides, and for a single
    // point (no silhouette) the bias-corrected centroid.
    residual[2 * n] = T(prior_weight) * (c[0] - T(prior.x()));
    residual[2 * n + 1] = T(prior_weight) * (c[1] - T(prior.y()));
    residual[2 * n + 2] = T(silhouette_weight) * SilhouetteResidual(c);
    return true;
  }

  // Return q's residuals (range, miss distance) against the section centred at c.
  template <typename T>
  void ReturnResidual(const T* c, const ScanPoint& q, T* r) const {
    ReturnRayResidual(c, q, round, radius, T(cos_a), T(sin_a), half_x, half_y, r);
  }

  // The silhouette term's bearing error.
  template <typename T>
  T SilhouetteResidual(const T* c) const {
    return SilhouetteBearingError(c, round, radius, T(cos_a), T(sin_a), half_x, half_y, mid_cos,
                                  mid_sin, edge_side, edge_rad);
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

SilhouetteTerm MakeSilhouetteTerm(const std::vector<ScanPoint>& points,
                                  const SilhouetteEdges& edges, const LegFitConfig& config) {
  if (points.empty()) return {};
  // The silhouette: the leg spans the beams from the first point to the last, each edge lying
  // within one beam step; its centre bearing is the mean of the outer beams' bearings. That
  // holds however wide the beam footprint makes the silhouette (it widens both edges alike),
  // and it does not depend on the range noise. A deviation from the paper, which fits the
  // points alone: with range noise comparable to the leg's size, the curvature of the predicted
  // ranges turns that noise into error across the beam (0.7 beam steps RMS for a 26 mm leg at
  // 1 m, against 0.2 with this term; LegFitTest).
  const ScanPoint& first = points.front();
  const ScanPoint& last = points.back();
  const double span = geometry::AngleDiff(last.angle, first.angle);
  const double mid = first.angle + 0.5 * span;
  // The beam step: from the outer beams, or for a single return from the edge seen beside it
  // (halfway to the next beam). A single return with no edge seen has no silhouette term.
  const std::optional<double> seen_edge = edges.before_rad ? edges.before_rad : edges.after_rad;
  double step = 0.0;
  if (last.beam != first.beam) {
    step = std::abs(span / (last.beam - first.beam));
  } else if (seen_edge) {
    step = 2.0 * std::abs(geometry::AngleDiff(*seen_edge, first.angle));
  }
  SilhouetteTerm term;
  term.mid_rad = mid;
  if (step > 0.0) {
    term.sigma_rad = config.silhouette_sigma_beams * step;
    // One edge seen and the other side open (the beam beyond returned nothing, or something
    // nearer, or the field of view ends): the outer point there need not be the leg's last, so
    // the centre between the outer beams would pull the leg toward the edge seen. The edge seen
    // and the leg's known section place it instead; one edge is known half as well as the mean
    // of two. For a leg seen by a few beams whatever left the side open; with more, only when the
    // side is cut (an occluder, the end of the field of view: the leg may go on for centimetres
    // there). Behind a dropout a leg goes on for a beam or so, its faces place it well, and the
    // one edge, which leans on the section's modelled orientation and the beam's footprint, did
    // worse (docking in warehouse_aisle.yaml, 200 runs: heading p99 before the code check 4.4
    // mrad with the outer beams for 6 or more returns, 5.1 with the edge for any number;
    // eval-layouts 9000 scenes 96.80 against 96.89 %). The sensor beside or under a large shelf
    // sees the nearest leg cut by the field of view's end with 8-13 returns, and the outer beams
    // put it 15-24 mm off across the beam (eval-layouts --class large_close --scenes-per-class
    // 1000 --seed0 5001: 99.07 -> 99.73 % with the edge).
    const bool one_edge = edges.before_rad.has_value() != edges.after_rad.has_value();
    const bool other_side_cut = edges.before_rad ? edges.after_cut : edges.before_cut;
    if (one_edge &&
        (static_cast<int>(points.size()) <= config.one_edge_max_points || other_side_cut)) {
      term.edge_rad = geometry::AngleDiff(*seen_edge, mid);
      term.edge_side = term.edge_rad < 0.0 ? -1 : 1;
      term.sigma_rad *= std::sqrt(2.0);
    }
  }
  return term;
}

double MixedEdgeNoise(double range_noise_m, const LegFitConfig& config) {
  // A floor: with the noise a scan of an ideal (simulated) or very quiet scanner estimates, a
  // fraction of a millimetre, a square leg's side-face return a millimetre off the fitted face
  // (a slightly wrong axis) would pass for a blend and lose its weight.
  return std::max(range_noise_m > 0.0 ? range_noise_m : config.range_sigma_m,
                  config.mixed_min_noise_m);
}

LegFitResult FitLeg(const std::vector<ScanPoint>& points, const geometry::LegModel& leg,
                    double axis_yaw_hint, const LegFitConfig& config, const SilhouetteEdges& edges,
                    double range_noise_m) {
  LegFitResult out;
  if (points.empty()) return out;
  // An outer return with a farther surface beyond it may be a blend of the two: its range lies
  // anywhere between them, so the fit keeps it only as far as the range noise explains it (the
  // posterior of a plain return). Taken at face value, two blended edge returns beside one plain
  // return put a 40 mm leg 3-4 cm behind its face (eval-layouts: legs a few centimetres in front
  // of a wall or a neighbour's leg, the 1080x856 then fitting the 1075x883 better).
  const double sigma = MixedEdgeNoise(range_noise_m, config);
  const MixedEdges mixed = FindMixedEdges(points, edges, sigma);
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

  const SilhouetteTerm silhouette = MakeSilhouetteTerm(points, edges, config);
  const double silhouette_weight =
      silhouette.sigma_rad > 0.0 ? config.range_sigma_m / silhouette.sigma_rad : 0.0;

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
                  config.prior_weight,
                  std::cos(silhouette.mid_rad),
                  std::sin(silhouette.mid_rad),
                  silhouette_weight,
                  silhouette.edge_side,
                  silhouette.edge_rad};
  using AutoDiff = ceres::TinySolverAutoDiffFunction<LegRayCost, Eigen::Dynamic, 2>;
  const AutoDiff function(cost);
  ceres::TinySolver<AutoDiff> solver;
  solver.options.max_num_iterations = config.max_iterations;
  Eigen::Vector2d c = c0;
  bool ok = true;
  constexpr int kIrlsRounds = 3;
  // The possible blends are weighed before the first solve, at the start: fitted first at face
  // value they would put the leg among them, and three rounds of weights do not move it back off
  // them (LegFitTest.BlendedEdgeReturnsDoNotPullTheLegOntoTheWallBehind: round legs 10 / 17 mm
  // behind their face with the weights from the second round, 6 / 4 mm with them from the start).
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double gap = mixed.Gap(i, points.size());
    if (gap == 0.0) continue;
    double r[2];
    cost.ReturnResidual(c.data(), points[i], r);
    weights[i] = MixedReturnSqrtWeight(r[0], sigma, gap, config.mixed_edge_share);
  }
  for (int round_i = 0; round_i < kIrlsRounds && ok; ++round_i) {
    solver.Solve(function, &c);
    ok = std::isfinite(c.x()) && std::isfinite(c.y());
    if (round_i + 1 == kIrlsRounds || !ok) break;
    for (std::size_t i = 0; i < points.size(); ++i) {
      double r[2];
      cost.ReturnResidual(c.data(), points[i], r);
      weights[i] = std::min(
          HuberSqrtWeight(std::hypot(r[0], r[1]), config.loss_scale_m),
          MixedReturnSqrtWeight(r[0], sigma, mixed.Gap(i, points.size()), config.mixed_edge_share));
    }
    // A missed edge beam (dropout, a trailing point removed) or a leg partly hidden behind
    // another cuts one side of the silhouette: the same robust loss.
    const double r_silhouette = silhouette_weight * cost.SilhouetteResidual(c.data());
    cost.silhouette_weight =
        silhouette_weight * HuberSqrtWeight(std::abs(r_silhouette), config.loss_scale_m);
  }

  out.centre = c;
  out.converged = ok;
  out.silhouette = silhouette;
  out.mixed = mixed;
  double sum_sq = 0.0;
  for (const auto& q : points) {
    double r[2];
    cost.ReturnResidual(c.data(), q, r);
    sum_sq += r[0] * r[0] + r[1] * r[1];
  }
  out.rms_m = std::sqrt(sum_sq / static_cast<double>(points.size()));
  return out;
}

}  // namespace shelfdock::perception
