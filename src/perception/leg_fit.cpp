#include "perception/leg_fit.hpp"

#include <cmath>
#include <numbers>

#include <ceres/ceres.h>
#include <Eigen/Eigenvalues>

#include "geometry/angle.hpp"

namespace shelfdock::perception {
namespace {

// Round leg. The printed Eq. 7, |dx^2 + dy^2 - l_h/2|, mixes a squared distance with a radius
// (a typo); its geometric intent is the distance of the point from the circle: |p - c| - r.
struct CircleResidual {
  CircleResidual(Eigen::Vector2d p, double radius) : p_(std::move(p)), radius_(radius) {}
  template <typename T>
  bool operator()(const T* const c, T* residual) const {
    const T dx = T(p_.x()) - c[0];
    const T dy = T(p_.y()) - c[1];
    residual[0] = ceres::sqrt(dx * dx + dy * dy + T(1e-12)) - T(radius_);
    return true;
  }
  Eigen::Vector2d p_;
  double radius_;
};

// Rectangular leg. The printed Eq. 5 takes absolute values before rotating into the leg's axes
// and compares against G_h/2 on both lines (typos); its intent is the distance of the point to
// the nearer of the faces it can lie on. Here the point q = R(-alpha) (p - c) is compared with
// each face of the G_h x G_w section whose outward normal faces the sensor (a hidden face
// cannot be hit), giving (normal offset, overshoot past the face's ends) for the nearest one.
struct BoxFaceResidual {
  BoxFaceResidual(Eigen::Vector2d p, double axis_yaw, double half_x, double half_y)
      : p_(std::move(p)),
        c_(std::cos(axis_yaw)),
        s_(std::sin(axis_yaw)),
        hx_(half_x),
        hy_(half_y) {}

  template <typename T>
  bool operator()(const T* const c, T* residual) const {
    const T dx = T(p_.x()) - c[0];
    const T dy = T(p_.y()) - c[1];
    const T qx = T(c_) * dx + T(s_) * dy;  // point in the leg's axes
    const T qy = T(-s_) * dx + T(c_) * dy;
    const T ox = T(c_) * (-c[0]) + T(s_) * (-c[1]);  // sensor (origin) in the leg's axes
    const T oy = T(-s_) * (-c[0]) + T(c_) * (-c[1]);
    bool found = false;
    T best_n(0), best_t(0);
    auto consider = [&](const T& normal, const T& tangent, double half_tangent) {
      const T over = ceres::abs(tangent) - T(half_tangent);
      const T t = over > T(0) ? over : T(0);
      if (!found || normal * normal + t * t < best_n * best_n + best_t * best_t) {
        best_n = normal;
        best_t = t;
        found = true;
      }
    };
    if (ox > T(hx_)) consider(qx - T(hx_), qy, hy_);
    if (ox < T(-hx_)) consider(-qx - T(hx_), qy, hy_);
    if (oy > T(hy_)) consider(qy - T(hy_), qx, hx_);
    if (oy < T(-hy_)) consider(-qy - T(hy_), qx, hx_);
    if (!found) consider(ceres::abs(qx) - T(hx_), qy, hy_);  // sensor inside the section
    residual[0] = best_n;
    residual[1] = best_t;
    return true;
  }
  Eigen::Vector2d p_;
  double c_, s_, hx_, hy_;
};

// Weak pull toward the bias-corrected centroid: one visible face fixes the centre only across
// the face, so along it the centroid decides.
struct PriorResidual {
  PriorResidual(Eigen::Vector2d c0, double weight) : c0_(std::move(c0)), w_(weight) {}
  template <typename T>
  bool operator()(const T* const c, T* residual) const {
    residual[0] = T(w_) * (c[0] - T(c0_.x()));
    residual[1] = T(w_) * (c[1] - T(c0_.y()));
    return true;
  }
  Eigen::Vector2d c0_;
  double w_;
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

  // Start behind the centroid: visible points lie on the near side of the leg.
  const bool round = leg.shape == geometry::LegShape::kCircle;
  const double depth = round ? 0.8 * leg.Radius() : 0.85 * 0.25 * (leg.length_m + leg.width_m);
  const Eigen::Vector2d view =
      centroid.norm() > 1e-9 ? centroid.normalized() : Eigen::Vector2d::UnitX();
  const Eigen::Vector2d c0 = centroid + depth * view;
  double c[2] = {c0.x(), c0.y()};

  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::HuberLoss loss(config.loss_scale_m);
  for (const auto& q : points) {
    if (round) {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<CircleResidual, 1 /* residuals */, 2 /* centre */>(
              new CircleResidual(q.p, leg.Radius())),
          &loss, c);
    } else {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<BoxFaceResidual, 2 /* normal, overshoot */, 2>(
              new BoxFaceResidual(q.p, out.axis_yaw, 0.5 * leg.length_m, 0.5 * leg.width_m)),
          &loss, c);
    }
  }
  if (config.prior_weight > 0.0) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PriorResidual, 2, 2>(
                                 new PriorResidual(c0, config.prior_weight)),
                             nullptr, c);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = config.max_iterations;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  out.centre = Eigen::Vector2d(c[0], c[1]);
  out.converged = summary.IsSolutionUsable();
  const double n = static_cast<double>(points.size());
  out.rms_m = std::sqrt(2.0 * summary.final_cost / n);
  return out;
}

}  // namespace shelfdock::perception
