#include "sim/layout_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shelfdock::sim::layout {

namespace {
constexpr int kMaxDraws = 200;

/// Distance along `dir` from the shelf centre at which the ray leaves the rectangle of leg
/// centres grown by the leg size: beyond it the standoff grows with the distance.
double ExitDistance(const ShelfInstance& shelf, const Eigen::Vector2d& dir_world) {
  const Eigen::Vector2d d = shelf.T_world_shelf.rotation().transpose() * dir_world;
  const double hx = 0.5 * (shelf.model.length_m + shelf.model.leg.length_m);
  const double hy = 0.5 * (shelf.model.width_m + shelf.model.leg.width_m);
  const double tx = std::abs(d.x()) > 1e-12 ? hx / std::abs(d.x()) : 1e9;
  const double ty = std::abs(d.y()) > 1e-12 ? hy / std::abs(d.y()) : 1e9;
  return std::min(tx, ty);
}

/// The point on the ray from the shelf centre along `dir_world` whose standoff is `standoff_m`
/// (bisection outside the footprint), or nullopt when the ray leaves the footprint already
/// farther than that from every leg.
std::optional<Eigen::Vector2d> PointAtStandoff(const ShelfInstance& shelf,
                                               const Eigen::Vector2d& dir_world,
                                               double standoff_m) {
  const Eigen::Vector2d c = shelf.T_world_shelf.translation();
  double lo = ExitDistance(shelf, dir_world);
  double hi = lo + standoff_m + shelf.model.Diagonal();
  if (Standoff(shelf, c + lo * dir_world) > standoff_m) return std::nullopt;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Standoff(shelf, c + mid * dir_world) < standoff_m ? lo : hi) = mid;
  }
  const Eigen::Vector2d p = c + hi * dir_world;
  if (std::abs(Standoff(shelf, p) - standoff_m) > 1e-3) return std::nullopt;
  return p;
}

bool InBand(const std::optional<SensorBand>& band, const Eigen::Vector2d& p_world) {
  if (!band) return true;
  const double y = (band->T_world_band.inverse() * p_world).y();
  return y >= band->min_y_m && y <= band->max_y_m;
}
}  // namespace

double Standoff(const ShelfInstance& shelf, const Eigen::Vector2d& p_world) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& c : shelf.model.LegCentres()) {
    best = std::min(best, (shelf.T_world_shelf * c - p_world).norm());
  }
  return best;
}

std::optional<geometry::Pose2> PlaceSensorFacing(const SceneBuilder& builder, SceneRng& rng,
                                                 const ShelfInstance& target, double min_dir_rad,
                                                 double max_dir_rad,
                                                 const std::optional<SensorBand>& band,
                                                 const LayoutConfig& config) {
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    const double standoff = rng.Uniform(config.min_standoff_m, config.max_standoff_m);
    const double dir = rng.Uniform(min_dir_rad, max_dir_rad);
    const auto p = PointAtStandoff(target, {std::cos(dir), std::sin(dir)}, standoff);
    if (!p || !InBand(band, *p) || builder.Clearance(*p) < config.sensor_clearance_m) continue;
    const Eigen::Vector2d to_target = target.T_world_shelf.translation() - *p;
    const double bearing = rng.Uniform(-config.max_bearing_rad, config.max_bearing_rad);
    return geometry::Pose2(p->x(), p->y(), std::atan2(to_target.y(), to_target.x()) - bearing);
  }
  return std::nullopt;
}

std::optional<geometry::Pose2> PlaceSensorNear(const SceneBuilder& builder, SceneRng& rng,
                                               const ShelfInstance& target, double radius_m,
                                               double clearance_m) {
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    const double r = radius_m * std::sqrt(rng.Uniform(0.0, 1.0));
    const double phi = rng.Angle();
    const Eigen::Vector2d p =
        target.T_world_shelf.translation() + r * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    if (builder.Clearance(p) < clearance_m) continue;
    return geometry::Pose2(p.x(), p.y(), rng.Angle());
  }
  return std::nullopt;
}

geometry::Pose2 DrawPreset(SceneRng& rng, const ShelfInstance& target, const LayoutConfig& config) {
  const double r = config.preset_error_xy_m * std::sqrt(rng.Uniform(0.0, 1.0));
  const double phi = rng.Angle();
  const double dyaw = rng.Uniform(-config.preset_error_yaw_rad, config.preset_error_yaw_rad);
  // The map may store the heading as any of the symmetric ones.
  const bool square = target.model.IsSquare();
  const double flip = rng.Int(0, square ? 3 : 1) * (square ? 0.5 : 1.0) * std::numbers::pi;
  const geometry::Pose2& T = target.T_world_shelf;
  return {T.x + r * std::cos(phi), T.y + r * std::sin(phi), T.yaw + dyaw + flip};
}

}  // namespace shelfdock::sim::layout
