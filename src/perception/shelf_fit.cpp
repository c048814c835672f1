#include "perception/shelf_fit.hpp"

#include <cmath>
#include <numbers>

#include <ceres/ceres.h>
#include <Eigen/Dense>

#include "geometry/angle.hpp"
#include "perception/model_match.hpp"

namespace shelfdock::perception {
namespace {

template <typename T>
T WrapAngleT(const T& a) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return a - T(kTwoPi) * ceres::floor((a + T(std::numbers::pi)) / T(kTwoPi));
}

// Keeps the heading in [-pi, pi) during the solve (as in Ceres' pose_graph_2d example).
struct AngleManifoldFunctor {
  template <typename T>
  bool Plus(const T* x, const T* delta, T* x_plus_delta) const {
    *x_plus_delta = WrapAngleT(*x + *delta);
    return true;
  }
  template <typename T>
  bool Minus(const T* y, const T* x, T* y_minus_x) const {
    *y_minus_x = WrapAngleT(*y - *x);
    return true;
  }
};

// Eq. 8-10 for one leg: u = (c_x, c_y) + R(c_alpha) (s_x L/2, s_y W/2) is the model corner the
// leg belongs to (Eq. 8-9 is the corner with s = (-1, -1)); residual = leg - u.
// Eq. 10 sums |dx| + |dy|: that is not rotation invariant, not differentiable at the optimum
// and not what the "nonlinear least squares" of Eq. 11 solves. We use the squared Euclidean
// distance (the maximum-likelihood choice for isotropic Gaussian leg errors), made robust to a
// wrong leg by the loss function.
struct CornerResidual {
  CornerResidual(Eigen::Vector2d leg, Eigen::Vector2d corner_shelf)
      : leg_(std::move(leg)), corner_(std::move(corner_shelf)) {}
  template <typename T>
  bool operator()(const T* const centre, const T* const yaw, T* residual) const {
    const T c = ceres::cos(*yaw);
    const T s = ceres::sin(*yaw);
    residual[0] = T(leg_.x()) - (centre[0] + c * T(corner_.x()) - s * T(corner_.y()));
    residual[1] = T(leg_.y()) - (centre[1] + s * T(corner_.x()) + c * T(corner_.y()));
    return true;
  }
  Eigen::Vector2d leg_;
  Eigen::Vector2d corner_;
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
  std::array<int, 4> corner_of{-1, -1, -1, -1};
  std::array<bool, 4> taken{false, false, false, false};
  for (int i = 0; i < count; ++i) {
    int best = 0;
    for (int k = 1; k < 4; ++k) {
      if ((T_init * corners[k] - legs[i]).norm() < (T_init * corners[best] - legs[i]).norm()) {
        best = k;
      }
    }
    if (taken[best]) return std::nullopt;
    taken[best] = true;
    corner_of[i] = best;
  }

  double centre[2] = {T_init.x, T_init.y};
  double yaw = T_init.yaw;
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::CauchyLoss loss(config.loss_scale_m);
  ceres::AutoDiffManifold<AngleManifoldFunctor, 1, 1> angle_manifold;
  for (int i = 0; i < count; ++i) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<CornerResidual, 2 /* residuals */,
                                                             2 /* centre */, 1 /* yaw */>(
                                 new CornerResidual(legs[i], corners[corner_of[i]])),
                             &loss, centre, &yaw);
  }
  problem.SetManifold(&yaw, &angle_manifold);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = config.max_iterations;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  ShelfFitResult out;
  out.T_lidar_shelf = geometry::Pose2(centre[0], centre[1], yaw);
  out.cost = summary.final_cost;
  out.converged = summary.IsSolutionUsable();
  out.legs_used = count;
  out.length_m = edges.long_m;
  out.width_m = edges.short_m;

  // Covariance: residual r_i = leg_i - (t + R c_i), so dr/dt = -I and dr/dyaw = -R' c_i.
  Eigen::MatrixXd J(2 * count, 3);
  double sum_sq = 0.0;
  const Eigen::Matrix2d R = out.T_lidar_shelf.rotation();
  Eigen::Matrix2d dR;
  dR << -R(1, 0), -R(0, 0), R(0, 0), -R(1, 0);  // d/dyaw of [c -s; s c]
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d& ci = corners[corner_of[i]];
    sum_sq += (legs[i] - out.T_lidar_shelf * ci).squaredNorm();
    J.block<2, 2>(2 * i, 0) = -Eigen::Matrix2d::Identity();
    J.block<2, 1>(2 * i, 2) = -dR * ci;
  }
  out.rms_m = std::sqrt(sum_sq / count);
  const double dof = std::max(1, 2 * count - 3);
  const double variance = std::max(sum_sq / dof, config.min_leg_sigma_m * config.min_leg_sigma_m);
  out.covariance = variance * (J.transpose() * J).inverse();
  return out;
}

}  // namespace shelfdock::perception
