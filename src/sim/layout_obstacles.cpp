#include "sim/layout_obstacles.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/line_of_sight.hpp"

namespace shelfdock::sim::layout {

namespace {
constexpr int kMaxDraws = 50;
// Clutter [m, rad]: around the preset within this radius, else anywhere in the field of view
// beyond the robot's own footprint; boxes (crates, bins, pallets) of these sides.
constexpr double kClutterPresetRadius_m = 1.5;
constexpr double kClutterMinRange_m = 0.3;
constexpr double kClutterMaxBearing_rad = 2.3;
constexpr double kClutterMinBox_m = 0.2, kClutterMaxBox_m = 1.2;

Eigen::Vector2d Unit(double angle_rad) { return {std::cos(angle_rad), std::sin(angle_rad)}; }

/// Boxes and posts: anything from black plastic to white paint, some of it glossy.
Material DrawObjectMaterial(SceneRng& rng) { return {rng.Uniform(0.1, 0.9), rng.Chance(0.2)}; }

/// Half the extent of an oriented rectangle along the unit direction `u`.
double Support(const geometry::Pose2& T_world_rect, double length_m, double width_m,
               const Eigen::Vector2d& u) {
  const Eigen::Vector2d d = T_world_rect.rotation().transpose() * u;
  return 0.5 * (length_m * std::abs(d.x()) + width_m * std::abs(d.y()));
}

/// A rectangle (box or square post) of the given size whose face nearest to `leg` along the
/// ray `u` lies `gap_m` before the leg centre.
bool TryAddRectangleOnRay(SceneBuilder& builder, const Eigen::Vector2d& leg,
                          const Eigen::Vector2d& u, double gap_m, double length_m, double width_m,
                          double yaw_rad, const Material& material, double min_gap_m) {
  Box box;
  box.T_world_box = geometry::Pose2(0.0, 0.0, yaw_rad);
  box.length_m = length_m;
  box.width_m = width_m;
  box.material = material;
  const Eigen::Vector2d c = leg - (gap_m + Support(box.T_world_box, length_m, width_m, u)) * u;
  box.T_world_box = geometry::Pose2(c.x(), c.y(), yaw_rad);
  return builder.TryAddBox(box, min_gap_m);
}

/// One occluder of a drawn kind on the ray toward `leg`.
bool TryAddOccluderOnRay(SceneBuilder& builder, SceneRng& rng, const Eigen::Vector2d& leg,
                         const Eigen::Vector2d& u, const LayoutConfig& config) {
  const double gap = rng.Uniform(config.occluder_min_gap_m, config.occluder_max_gap_m);
  const Material material = DrawObjectMaterial(rng);
  switch (rng.Int(0, 3)) {
    case 0: {  // a box, a crate
      const double a = rng.Uniform(config.box_min_side_m, config.box_max_side_m);
      const double b = rng.Uniform(config.box_min_side_m, config.box_max_side_m);
      return TryAddRectangleOnRay(builder, leg, u, gap, a, b, rng.Angle(), material,
                                  config.min_object_gap_m);
    }
    case 1: {  // a square post
      const double side = rng.Uniform(config.post_min_size_m, config.post_max_size_m);
      return TryAddRectangleOnRay(builder, leg, u, gap, side, side, rng.Angle(), material,
                                  config.min_object_gap_m);
    }
    case 2: {  // a round post
      RoundPost post;
      post.radius_m = 0.5 * rng.Uniform(config.post_min_size_m, config.post_max_size_m);
      post.centre = leg - (gap + post.radius_m) * u;
      post.material = material;
      return builder.TryAddRoundPost(post, config.min_object_gap_m);
    }
    default: {  // a person, one leg on the ray, the other beside it
      const double r = rng.Uniform(config.person_min_leg_radius_m, config.person_max_leg_radius_m);
      const Eigen::Vector2d first = leg - (gap + r) * u;
      const Eigen::Vector2d second = first + config.person_leg_spacing_m * Unit(rng.Angle());
      return builder.TryAddPerson(first, second, r, config.min_object_gap_m);
    }
  }
}

/// Where a clutter object goes: around the preset (half the time, when there is one) or
/// anywhere in the sensor's field of view within clutter_max_range_m.
Eigen::Vector2d DrawClutterSpot(SceneRng& rng, const geometry::Pose2& T_world_lidar,
                                const std::optional<geometry::Pose2>& T_world_preset,
                                const LayoutConfig& config) {
  if (T_world_preset && rng.Chance(0.5)) {
    const double r = kClutterPresetRadius_m * std::sqrt(rng.Uniform(0.0, 1.0));
    return T_world_preset->translation() + r * Unit(rng.Angle());
  }
  const double range = rng.Uniform(kClutterMinRange_m, config.clutter_max_range_m);
  const double bearing = rng.Uniform(-kClutterMaxBearing_rad, kClutterMaxBearing_rad);
  return T_world_lidar * Eigen::Vector2d(range * Unit(bearing));
}

bool TryAddClutterPost(SceneBuilder& builder, SceneRng& rng, const Eigen::Vector2d& spot,
                       const LayoutConfig& config) {
  const double size = rng.Uniform(config.clutter_min_post_m, config.clutter_max_post_m);
  const Material material = DrawObjectMaterial(rng);
  if (rng.Chance(0.5)) {
    RoundPost post;
    post.centre = spot;
    post.radius_m = 0.5 * size;
    post.material = material;
    return builder.TryAddRoundPost(post, config.min_object_gap_m);
  }
  Box post;
  post.T_world_box = geometry::Pose2(spot.x(), spot.y(), rng.Angle());
  post.length_m = post.width_m = size;
  post.material = material;
  return builder.TryAddBox(post, config.min_object_gap_m);
}

bool TryAddClutterBox(SceneBuilder& builder, SceneRng& rng, const Eigen::Vector2d& spot,
                      const LayoutConfig& config) {
  Box box;
  box.T_world_box = geometry::Pose2(spot.x(), spot.y(), rng.Angle());
  box.length_m = rng.Uniform(kClutterMinBox_m, kClutterMaxBox_m);
  box.width_m = rng.Uniform(kClutterMinBox_m, kClutterMaxBox_m);
  box.material = DrawObjectMaterial(rng);
  return builder.TryAddBox(box, config.min_object_gap_m);
}

bool TryAddStandingPerson(SceneBuilder& builder, SceneRng& rng, const Eigen::Vector2d& spot,
                          const LayoutConfig& config) {
  const double r = rng.Uniform(config.person_min_leg_radius_m, config.person_max_leg_radius_m);
  const Eigen::Vector2d half = 0.5 * config.person_leg_spacing_m * Unit(rng.Angle());
  return builder.TryAddPerson(spot + half, spot - half, r, config.min_object_gap_m);
}

/// Up to kMaxDraws tries of `try_add` at fresh spots.
template <typename TryAdd>
void AddWithRetries(TryAdd try_add) {
  for (int draw = 0; draw < kMaxDraws && !try_add(); ++draw) {
  }
}
}  // namespace

std::optional<int> AddOccluder(SceneBuilder& builder, SceneRng& rng, const ShelfInstance& target,
                               const geometry::Pose2& T_world_lidar, const LayoutConfig& config) {
  const auto legs = target.model.LegCentres();
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    const int index = rng.Int(0, 3);
    const Eigen::Vector2d leg = target.T_world_shelf * legs[static_cast<std::size_t>(index)];
    const Eigen::Vector2d u = (leg - T_world_lidar.translation()).normalized();
    if (TryAddOccluderOnRay(builder, rng, leg, u, config)) return index;
  }
  return std::nullopt;
}

bool AddPersonBesideLeg(SceneBuilder& builder, SceneRng& rng, const ShelfInstance& target,
                        const geometry::Pose2& T_world_lidar, const LidarConfig& lidar,
                        const LayoutConfig& config) {
  const LegSight sight = ComputeLegSight(builder.world(), T_world_lidar, lidar, target.id);
  std::vector<int> visible;
  for (int i = 0; i < 4; ++i) {
    if (sight.beams[static_cast<std::size_t>(i)] >= config.min_beams_in_sight) visible.push_back(i);
  }
  if (visible.empty()) return false;
  const auto legs = target.model.LegCentres();
  // Trousers may brush the leg: only a few millimetres of clearance are asked for here.
  constexpr double kTouchGap_m = 0.005;
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    const int index = visible[rng.Index(visible.size())];
    const Eigen::Vector2d leg = target.T_world_shelf * legs[static_cast<std::size_t>(index)];
    const double distance = rng.Uniform(config.person_min_distance_m, config.person_max_distance_m);
    const Eigen::Vector2d near = leg + distance * Unit(rng.Angle());
    const Eigen::Vector2d far = near + config.person_leg_spacing_m * Unit(rng.Angle());
    if ((far - leg).norm() < distance) continue;  // `near` must be the nearer leg
    const double r = rng.Uniform(config.person_min_leg_radius_m, config.person_max_leg_radius_m);
    if (builder.TryAddPerson(near, far, r, kTouchGap_m)) return true;
  }
  return false;
}

void AddAislePeople(SceneBuilder& builder, SceneRng& rng, const geometry::Pose2& T_world_aisle,
                    double x0, double x1, double width_m, const LayoutConfig& config) {
  const int people = rng.Int(0, 2);
  for (int i = 0; i < people; ++i) {
    AddWithRetries([&] {
      const double x = rng.Uniform(x0, x1);
      const double y = rng.Uniform(0.3, width_m - 0.3);
      const Eigen::Vector2d spot = T_world_aisle * Eigen::Vector2d(x, y);
      return TryAddStandingPerson(builder, rng, spot, config);
    });
  }
}

void AddClutter(SceneBuilder& builder, SceneRng& rng, const geometry::Pose2& T_world_lidar,
                const std::optional<geometry::Pose2>& T_world_preset, const LayoutConfig& config) {
  auto spot = [&] { return DrawClutterSpot(rng, T_world_lidar, T_world_preset, config); };
  const int posts = rng.Int(config.clutter_min_posts, config.clutter_max_posts);
  for (int i = 0; i < posts; ++i) {
    AddWithRetries([&] { return TryAddClutterPost(builder, rng, spot(), config); });
  }
  const int boxes = rng.Int(0, config.clutter_max_boxes);
  for (int i = 0; i < boxes; ++i) {
    AddWithRetries([&] { return TryAddClutterBox(builder, rng, spot(), config); });
  }
  const int people = rng.Int(0, config.clutter_max_people);
  for (int i = 0; i < people; ++i) {
    AddWithRetries([&] { return TryAddStandingPerson(builder, rng, spot(), config); });
  }
}

}  // namespace shelfdock::sim::layout
