#pragma once

#include <limits>
#include <optional>

#include <Eigen/Core>

#include "geometry/config_violation.hpp"

namespace shelfdock::sim {

/// How a surface answers a laser pulse. Dark surfaces return little energy, shiny ones mirror
/// the pulse away at oblique incidence: both raise the dropout probability (see LidarConfig).
struct Material {
  double reflectivity = 0.6;  ///< [0..1] diffuse reflectance at the LiDAR's wavelength
  bool shiny = false;         ///< specular (polished metal, glossy paint)
};

/// The first impossible value of a material: reflectivity in [0, 1]. Keys as in scenario files,
/// where `reflectivity` and `shiny` sit beside the object's other keys.
std::optional<geometry::ConfigViolation> FindConfigViolation(const Material& material);

/// What a primitive belongs to, so a hit can be traced back to its object (scoring, tests).
enum class ObjectKind { kShelfLeg, kWall, kBox, kPost, kPerson, kRobot, kFloor };

/// One exact shape for the ray caster: a circle (centre a, radius) or a segment (a to b).
/// Boxes and polygons are made of segments; round legs, posts and people's legs are circles.
/// Every primitive is a vertical prism from the floor up to `height_m`.
struct Primitive {
  enum class Shape { kCircle, kSegment };
  Shape shape = Shape::kSegment;
  Eigen::Vector2d a = Eigen::Vector2d::Zero();  ///< [m] circle centre or segment start (world)
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  ///< [m] segment end (unused for circles)
  double radius_m = 0.0;                        ///< [m] circles only
  double height_m = std::numeric_limits<double>::infinity();  ///< [m] top above the floor
  Material material;
  ObjectKind kind = ObjectKind::kWall;
  int object_id = -1;  ///< shelf id for legs, else the object's index in its World list
  int part = 0;        ///< leg index for shelf legs and people's legs, else 0

  static Primitive Circle(const Eigen::Vector2d& centre, double radius_m);
  static Primitive Segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

  /// Axis-aligned bounds in the world frame (min, max).
  void Bounds(Eigen::Vector2d* min, Eigen::Vector2d* max) const;
};

/// A horizontal ray: p(t) = origin + t * dir, `dir` of unit length, t >= 0 in metres.
struct Ray2 {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  Eigen::Vector2d dir = Eigen::Vector2d::UnitX();
};

/// Distance along the ray to the first crossing of the primitive's outline, or +infinity.
/// Exact: the quadratic |o + t d - c|^2 = r^2 for circles, a 2x2 solve for segments. A ray that
/// starts inside a circle sees its far wall (as a LiDAR inside a hollow tube would).
double IntersectRay(const Ray2& ray, const Primitive& primitive);

/// The outward unit normal of the primitive at a point on it (segments: the side facing `from`).
Eigen::Vector2d SurfaceNormal(const Primitive& primitive, const Eigen::Vector2d& point,
                              const Eigen::Vector2d& from);

}  // namespace shelfdock::sim
