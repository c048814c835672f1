#pragma once
// The silhouette of a leg section seen from the sensor: templated for automatic differentiation
// (ceres::TinySolverAutoDiffFunction in the leg fit) and used with doubles by the evidence.

#include <cmath>

namespace shelfdock::perception {

/// Bearings of a leg section's outline as seen from the sensor (the origin), relative to the
/// bearing (mid_cos, mid_sin): a circle's two tangents (half the view when the sensor is inside
/// it), or a box's extreme corners (its x axis at (cos_a, sin_a)). `c` is the section's centre.
/// The leg fit's silhouette term (automatic differentiation) and the evidence's expected leg
/// widths (LegSilhouetteAngle) both use it.
template <typename T>
void SilhouetteBearings(const T* c, bool round, double radius, const T& cos_a, const T& sin_a,
                        double half_x, double half_y, double mid_cos, double mid_sin, T& lo,
                        T& hi) {
  using std::atan2;
  auto bearing = [&](const T& x, const T& y) {
    return atan2(T(mid_cos) * y - T(mid_sin) * x, T(mid_cos) * x + T(mid_sin) * y);
  };
  if (round) {
    using std::asin;
    using std::sqrt;
    const T b = bearing(c[0], c[1]);
    const T d = sqrt(c[0] * c[0] + c[1] * c[1]);
    const T half = d > T(radius) ? asin(T(radius) / d) : T(0.5 * 3.141592653589793);
    lo = b - half;
    hi = b + half;
    return;
  }
  lo = T(1e9);
  hi = T(-1e9);
  for (const double sx : {-half_x, half_x}) {
    for (const double sy : {-half_y, half_y}) {
      const T b =
          bearing(c[0] + (cos_a * T(sx) - sin_a * T(sy)), c[1] + (sin_a * T(sx) + cos_a * T(sy)));
      if (b < lo) lo = b;
      if (b > hi) hi = b;
    }
  }
}

/// The silhouette term's bearing error (leg fit, shelf fit on the returns): of the predicted
/// outline's centre relative to (mid_cos, mid_sin) when edge_side is 0 (both edges seen, or
/// neither), else of the outline's edge on that side (-1 the smaller bearing) relative to the
/// edge seen at edge_rad.
template <typename T>
T SilhouetteBearingError(const T* c, bool round, double radius, const T& cos_a, const T& sin_a,
                         double half_x, double half_y, double mid_cos, double mid_sin,
                         int edge_side, double edge_rad) {
  T lo, hi;
  SilhouetteBearings(c, round, radius, cos_a, sin_a, half_x, half_y, mid_cos, mid_sin, lo, hi);
  if (edge_side < 0) return lo - T(edge_rad);
  if (edge_side > 0) return hi - T(edge_rad);
  return T(0.5) * (lo + hi);
}

}  // namespace shelfdock::perception
