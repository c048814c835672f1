#include "perception/known_legs.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "perception/leg_fit.hpp"
#include "perception/silhouette_edges.hpp"

namespace shelfdock::perception {
namespace {

// A leg's points and the edges of its outline the scan shows.
struct LegRunPoints {
  std::vector<ScanPoint> points;
  SilhouetteEdges edges;
};

// The points of the leg expected at `predicted`: the run of consecutive points (beam order,
// neighbours closer than gap_m) holding the point nearest to it, cut to search_radius_m. A box or
// a post near the leg is another run and stays out; a run wider than the leg (something touching
// it, merged) is no leg measurement at all: empty. The run's outline edges count only when
// nothing was cut from it.
LegRunPoints LegRun(const std::vector<ScanPoint>& points, const Eigen::Vector2d& predicted,
                    const geometry::LegModel& leg, const KnownLegsConfig& config) {
  std::size_t nearest = points.size();
  double best = config.search_radius_m;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = (points[i].p - predicted).norm();
    if (d <= best) {
      best = d;
      nearest = i;
    }
  }
  if (nearest == points.size()) return {};
  std::size_t first = nearest, last = nearest;
  while (first > 0 && (points[first - 1].p - points[first].p).norm() < config.gap_m) --first;
  while (last + 1 < points.size() && (points[last + 1].p - points[last].p).norm() < config.gap_m) {
    ++last;
  }
  if ((points[last].p - points[first].p).norm() > leg.Extent() + config.size_margin_m) return {};
  LegRunPoints run;
  for (std::size_t i = first; i <= last; ++i) {
    if ((points[i].p - predicted).norm() <= config.search_radius_m) run.points.push_back(points[i]);
  }
  if (run.points.size() == last - first + 1) {
    run.edges = FindSilhouetteEdges(points, points[first], points[last], config.gap_m);
  }
  return run;
}

}  // namespace

std::optional<KnownLegsResult> MeasureKnownLegs(const std::vector<ScanPoint>& points,
                                                const geometry::Pose2& T_lidar_shelf_prior,
                                                const geometry::ShelfModel& model,
                                                const std::array<bool, 4>& use,
                                                const KnownLegsConfig& config) {
  const auto corners = model.LegCentres();
  std::vector<Eigen::Vector2d> in_shelf, in_lidar;
  for (int k = 0; k < 4; ++k) {
    if (!use[static_cast<std::size_t>(k)]) continue;
    const Eigen::Vector2d predicted = T_lidar_shelf_prior * corners[static_cast<std::size_t>(k)];
    const LegRunPoints run = LegRun(points, predicted, model.leg, config);
    if (static_cast<int>(run.points.size()) < config.min_points) continue;
    const LegFitResult fit =
        FitLeg(run.points, model.leg, T_lidar_shelf_prior.yaw, config.leg_fit, run.edges);
    if (!fit.converged) continue;
    // The prior is good to a few millimetres here: a leg found farther off is something else.
    if ((fit.centre - predicted).norm() > config.max_offset_m) return std::nullopt;
    in_shelf.push_back(corners[static_cast<std::size_t>(k)]);
    in_lidar.push_back(fit.centre);
  }
  const int n = static_cast<int>(in_shelf.size());
  if (n < 2) return std::nullopt;

  // Rigid alignment of the model's corners (shelf frame) onto the fitted centres (lidar frame):
  // the rotation from the cross and dot sums of the centred point sets, the translation from the
  // centroids (2D Kabsch, closed form).
  Eigen::Vector2d m_mean = Eigen::Vector2d::Zero(), d_mean = Eigen::Vector2d::Zero();
  for (int i = 0; i < n; ++i) {
    m_mean += in_shelf[i];
    d_mean += in_lidar[i];
  }
  m_mean /= n;
  d_mean /= n;
  double dot = 0.0, cross = 0.0, spread = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d m = in_shelf[i] - m_mean;
    const Eigen::Vector2d d = in_lidar[i] - d_mean;
    dot += m.dot(d);
    cross += m.x() * d.y() - m.y() * d.x();
    spread += m.squaredNorm();
  }
  const double yaw = std::atan2(cross, dot);
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  const Eigen::Vector2d t = d_mean - R * m_mean;
  KnownLegsResult out;
  out.T_lidar_shelf = geometry::Pose2(t.x(), t.y(), yaw);
  out.legs = n;
  double sum_sq = 0.0;
  for (int i = 0; i < n; ++i) sum_sq += (R * in_shelf[i] + t - in_lidar[i]).squaredNorm();
  out.rms_m = std::sqrt(sum_sq / n);
  if (out.rms_m > config.max_rms_m) return std::nullopt;

  // Covariance with each fitted centre isotropic with std s: the heading from the spread of the
  // corners, s^2 / sum |m_i - m_mean|^2; the centroid s^2 / n; the shelf origin sits at -m_mean
  // from the corners' centroid (shelf frame), so a heading error moves it across that lever.
  const double s2 = config.leg_sigma_m * config.leg_sigma_m;
  const double var_yaw = s2 / spread;
  const Eigen::Vector2d lever = R * Eigen::Vector2d(m_mean.y(), -m_mean.x());  // d t / d yaw
  out.covariance.setZero();
  out.covariance.topLeftCorner<2, 2>() =
      (s2 / n) * Eigen::Matrix2d::Identity() + var_yaw * lever * lever.transpose();
  out.covariance.topRightCorner<2, 1>() = var_yaw * lever;
  out.covariance.bottomLeftCorner<1, 2>() = var_yaw * lever.transpose();
  out.covariance(2, 2) = var_yaw;
  return out;
}

}  // namespace shelfdock::perception
