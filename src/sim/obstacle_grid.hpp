#pragma once

#include <span>
#include <vector>

#include "sim/primitive.hpp"

namespace shelfdock::sim {

/// One horizontal cast: the ray, how far to look, and the beam's height along it so that
/// primitives lower than the beam are passed over (a tilted scan plane climbs or sinks with
/// range). The beam's height at distance t is z0_m + t * dz_dt.
struct CastQuery {
  Ray2 ray;
  double max_t_m = 25.0;  ///< [m] horizontal distance limit
  double z0_m = 0.2;      ///< [m] beam height at the origin
  double dz_dt = 0.0;     ///< [m/m] climb per horizontal metre (tan of the elevation)
};

/// The nearest primitive along a cast; `primitive` is null on a miss.
struct RayHit {
  double t_m = std::numeric_limits<double>::infinity();  ///< [m] horizontal distance
  const Primitive* primitive = nullptr;
};

/// Tests one primitive against a cast, including the height check.
bool CastAgainst(const CastQuery& query, const Primitive& primitive, RayHit* best);

/// Brute force over a few primitives (people, moving robots).
RayHit CastAll(const CastQuery& query, std::span<const Primitive> primitives);

/// A uniform grid over static primitives. Casting walks the cells the ray crosses in order
/// (Amanatides & Woo) and stops at the first cell whose exit lies beyond the best hit, so the
/// cost grows with the distance travelled, not with the size of the world.
class ObstacleGrid {
 public:
  ObstacleGrid() = default;
  ObstacleGrid(std::vector<Primitive> primitives, double cell_size_m = 0.5);

  RayHit Cast(const CastQuery& query) const;

  const std::vector<Primitive>& primitives() const { return primitives_; }

 private:
  std::vector<Primitive> primitives_;
  Eigen::Vector2d min_ = Eigen::Vector2d::Zero();
  double cell_ = 0.5;
  int nx_ = 0;
  int ny_ = 0;
  std::vector<int> cell_start_;  ///< CSR: primitives of cell k are indices_[start[k]..start[k+1])
  std::vector<int> indices_;
};

}  // namespace shelfdock::sim
