#pragma once
// Internal to the layout generator: a seeded random stream and a world under construction that
// knows where its solids are, so that a new object can be refused where it would overlap.

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "geometry/pose2.hpp"
#include "sim/world.hpp"

namespace shelfdock::sim::layout {

/// Uniform draws from a 64-bit Mersenne Twister, written out so that a seed gives the same
/// scene with any standard library (std::uniform_real_distribution is implementation-defined).
/// Callers make one draw per statement: the order in which a call's arguments are evaluated is
/// unspecified, and the scene must not depend on the compiler.
class SceneRng {
 public:
  /// One independent stream per (seed, stream, attempt): std::seed_seq is fully specified.
  SceneRng(std::uint64_t seed, std::uint64_t stream, std::uint64_t attempt);

  double Uniform(double lo, double hi);  ///< in [lo, hi)
  int Int(int lo, int hi);               ///< in [lo, hi], both included
  std::size_t Index(std::size_t n);      ///< in [0, n), n > 0
  bool Chance(double p);                 ///< true with probability p
  double Angle();                        ///< in [-pi, pi)
  std::uint64_t Bits() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

/// A solid's footprint on the floor: a convex polygon (box, rectangular leg), a circle, or an
/// open polyline (wall).
struct Solid {
  enum class Kind { kPolygon, kCircle, kPolyline };
  Kind kind = Kind::kCircle;
  std::vector<Eigen::Vector2d> points;  ///< polygon corners (counter-clockwise) or polyline
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< circles
  double radius_m = 0.0;                             ///< circles

  static Solid Circle(const Eigen::Vector2d& centre, double radius_m);
  static Solid Rectangle(const geometry::Pose2& T_world_rect, double length_m, double width_m);
  static Solid Polyline(std::vector<Eigen::Vector2d> points);
};

/// Distance between two solids' outlines; 0 when they touch or one holds the other.
double SolidDistance(const Solid& a, const Solid& b);
/// Distance from a point to a solid; 0 inside it.
double SolidDistance(const Solid& a, const Eigen::Vector2d& p);

/// A World being built, with the footprints of everything placed so far. The TryAdd calls
/// refuse (and return false) an object closer than `gap_m` to anything already there or to a
/// point kept free (the sensor).
class SceneBuilder {
 public:
  void AddShelf(const ShelfInstance& shelf);
  void AddWall(const Wall& wall);
  void AddBox(const Box& box);  ///< unconditionally (racks, pallets placed by construction)
  bool TryAddBox(const Box& box, double gap_m);
  bool TryAddRoundPost(const RoundPost& post, double gap_m);
  /// A person standing still with leg centres `left` and `right`.
  bool TryAddPerson(const Eigen::Vector2d& left, const Eigen::Vector2d& right, double leg_radius_m,
                    double gap_m);
  /// Keeps a disc free from now on (the sensor and the robot around it).
  void KeepFree(const Eigen::Vector2d& centre, double radius_m);

  /// Distance from `p` to the nearest solid placed so far.
  double Clearance(const Eigen::Vector2d& p) const;
  /// Bounding box of everything placed and kept free (min, max), world frame.
  void Bounds(Eigen::Vector2d* min, Eigen::Vector2d* max) const;

  World& world() { return world_; }
  const World& world() const { return world_; }

 private:
  bool Fits(const std::vector<Solid>& added, double gap_m) const;

  World world_;
  std::vector<Solid> solids_;
  std::vector<Solid> free_;  ///< discs kept free
};

}  // namespace shelfdock::sim::layout
