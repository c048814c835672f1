#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geometry/config_violation.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "sim/path_motion.hpp"
#include "sim/primitive.hpp"

namespace shelfdock::sim {

/// A shelf standing in the world. Only its legs reach the scan plane (the deck is above it).
struct ShelfInstance {
  int id = 0;
  geometry::ShelfModel model;
  geometry::Pose2 T_world_shelf;
  Material leg_material{0.15, false};  ///< painted steel legs are dark: the paper's dropouts
  /// As built: each leg's centre offset and twist from its design place, in the shelf frame,
  /// indexed as geometry::ShelfModel::LegCentres(); empty: every leg where the model puts it.
  /// A welded frame is a few millimetres off its drawing, and a leg may stand turned.
  std::vector<geometry::Pose2> legs_as_built;
};

/// The loosest build tolerance ShelfInstance::legs_as_built may describe: beyond a few
/// centimetres a leg stands elsewhere, beyond 45 degrees a square leg turns into itself.
inline constexpr double kMaxLegBuildError_m = 0.05;  ///< [m] along each shelf axis
inline constexpr double kMaxLegTwist_rad = 0.785;    ///< [rad]

/// The true footprint of one shelf leg in the world frame, for clearance checks when docking.
struct LegFootprint {
  int shelf_id = 0;
  int leg_index = 0;  ///< as geometry::ShelfModel::LegCentres()
  geometry::LegShape shape = geometry::LegShape::kRectangle;
  geometry::Pose2 T_world_leg;  ///< centre, yaw of the shelf plus the leg's twist as built
  double length_m = 0.0;        ///< [m] along the shelf's long side (diameter for round legs)
  double width_m = 0.0;         ///< [m]

  /// Corners counter-clockwise (rectangle legs; the bounding square for round legs).
  std::array<Eigen::Vector2d, 4> Corners() const;
};

/// A wall or any fixed outline: a polyline, closed for polygons (boxes, pillars, racks).
struct Wall {
  std::vector<Eigen::Vector2d> points;  ///< [m] world frame, at least two
  bool closed = false;
  double height_m = std::numeric_limits<double>::infinity();  ///< [m]
  Material material{0.6, false};
};

/// An oriented box on the floor: a pallet, a crate, a square post.
struct Box {
  geometry::Pose2 T_world_box;                                ///< centre and heading
  double length_m = 1.0;                                      ///< [m] along the box's x
  double width_m = 1.0;                                       ///< [m]
  double height_m = std::numeric_limits<double>::infinity();  ///< [m]
  Material material{0.5, false};
};

/// A round post or pillar.
struct RoundPost {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< [m] world frame
  double radius_m = 0.1;                             ///< [m]
  Material material{0.5, false};
};

/// A walking person, seen by a 2D LiDAR at shin height as two legs that swing fore and aft
/// in anti-phase while the body moves along the path.
struct Person {
  PathMotion path;
  double leg_radius_m = 0.06;  ///< [m]
  double leg_spacing_m = 0.2;  ///< [m] between the leg centres, across the walking direction
  double stride_m = 0.6;       ///< [m] fore-aft swing amplitude peak to peak
  double height_m = 1.7;       ///< [m]
  Material material{0.4, false};

  /// Centres of the two legs at time t.
  std::array<Eigen::Vector2d, 2> LegCentresAt(double t_s) const;
};

/// Another robot driving a path: a moving box.
struct MovingRobot {
  PathMotion path;
  double length_m = 0.9;  ///< [m]
  double width_m = 0.6;   ///< [m]
  double height_m = 0.4;  ///< [m]
  Material material{0.5, true};

  Box BoxAt(double t_s) const;
};

/// The first impossible value of an object, keys as in a scenario file's entry for it (the
/// material's and the path's keys beside the object's own: `reflectivity`, `speed`): positive
/// sizes and heights, reflectivities in [0, 1]. A shelf's model is checked with its own file
/// (geometry::FindConfigViolation), a wall's points by the loader (at least two).
std::optional<geometry::ConfigViolation> FindConfigViolation(const ShelfInstance& shelf);
std::optional<geometry::ConfigViolation> FindConfigViolation(const Wall& wall);
std::optional<geometry::ConfigViolation> FindConfigViolation(const Box& box);
std::optional<geometry::ConfigViolation> FindConfigViolation(const Person& person);
std::optional<geometry::ConfigViolation> FindConfigViolation(const MovingRobot& robot);

/// Primitive generation, one function per object kind. `index` tags the primitives.
void AppendShelfLegs(const ShelfInstance& shelf, std::vector<Primitive>* out);
void AppendWall(const Wall& wall, int index, std::vector<Primitive>* out);
void AppendBox(const Box& box, ObjectKind kind, int index, std::vector<Primitive>* out);
void AppendRoundPost(const RoundPost& post, int index, std::vector<Primitive>* out);
void AppendPerson(const Person& person, double t_s, int index, std::vector<Primitive>* out);
std::vector<LegFootprint> ShelfLegFootprints(const ShelfInstance& shelf);

}  // namespace shelfdock::sim
