#pragma once
// Ray-cast residuals of one LiDAR beam against a leg section, for the leg fit (3.3). Templated
// for automatic differentiation (ceres::TinySolverAutoDiffFunction).

#include <cmath>
#include <utility>

#include <ceres/jet.h>

#include "perception/scan_point.hpp"

namespace shelfdock::perception {

// Residuals of one beam against a leg section, by ray casting from the sensor (the origin):
// (measured range - predicted range of the first hit, miss distance). LiDAR noise is along the
// beam, so the range residual is the maximum-likelihood one; the paper's point-to-surface
// distances (Eq. 5, Eq. 7) are biased toward the sensor when the noise is comparable to the leg
// radius (|p - c| is convex in the noise) and pick the wrong face near a corner.
// A beam that misses the predicted section gets the range residual at its closest approach
// plus the miss distance, so the residual is continuous across the silhouette.

/// Round leg: b = u.c along the beam, e = u x c across it; hit at t = b - sqrt(r^2 - e^2).
template <typename T>
void CircleRayResidual(const T* c, double ux, double uy, double range, double radius, T* out) {
  const T b = T(ux) * c[0] + T(uy) * c[1];
  const T e = T(ux) * c[1] - T(uy) * c[0];
  const T e_abs = e < T(0) ? -e : e;
  if (e_abs < T(radius)) {
    // The floor keeps the derivative finite at the tangent.
    const T h2 = T(radius * radius) - e * e;
    const T h = ceres::sqrt(h2 > T(1e-8) ? h2 : T(1e-8));
    out[0] = T(range) - (b - h);
    out[1] = T(0);
  } else {
    out[0] = T(range) - b;
    out[1] = e_abs - T(radius);
  }
}

/// Rectangular leg: slab test in the leg's axes (x along G_h). A beam that misses the box is
/// measured against the box's corner nearest to it across the beam (the silhouette corner on
/// its side): the range residual at that corner's distance along the beam, the miss distance
/// across it, as for a round leg. The slab test's own gap between leaving one slab and entering
/// the other is a distance along the beam: for a beam nearly parallel to a face (a leg seen
/// face-on, beside it a return that a wide beam spot or the noise put just past its edge) it
/// grows as 1 / sin of the grazing angle, a return 12 mm beside a 40 mm leg at 1.6 m then
/// counting a metre off and pulling a shelf fitted to its legs' returns 5 cm and 60 mrad away
/// (independent generator, against_wall seed 1 scene 84).
template <typename T>
void BoxRayResidual(const T* c, double ux, double uy, double range, const T& cos_a, const T& sin_a,
                    double half_x, double half_y, T* out) {
  // Ray origin (the sensor) and direction in the leg's axes.
  const T o[2] = {-(cos_a * c[0] + sin_a * c[1]), -(-sin_a * c[0] + cos_a * c[1])};
  const T d[2] = {cos_a * T(ux) + sin_a * T(uy), -sin_a * T(ux) + cos_a * T(uy)};
  const double h[2] = {half_x, half_y};
  T t_in(-1e9), t_out(1e9);
  for (int k = 0; k < 2; ++k) {
    const T dk = (d[k] < T(0) ? -d[k] : d[k]) < T(1e-9) ? T(d[k] < T(0) ? -1e-9 : 1e-9) : d[k];
    T ta = (T(-h[k]) - o[k]) / dk;
    T tb = (T(h[k]) - o[k]) / dk;
    if (tb < ta) std::swap(ta, tb);
    if (ta > t_in) t_in = ta;
    if (tb < t_out) t_out = tb;
  }
  if (t_in <= t_out) {
    out[0] = T(range) - t_in;
    out[1] = T(0);
    return;
  }
  // Missed: every corner lies on one side of the beam; the nearest across it.
  T best_along(0), best_across(1e9);
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      const T px = c[0] + cos_a * T(sx * half_x) - sin_a * T(sy * half_y);
      const T py = c[1] + sin_a * T(sx * half_x) + cos_a * T(sy * half_y);
      const T across = T(ux) * py - T(uy) * px;
      const T across_abs = across < T(0) ? -across : across;
      if (across_abs < best_across) {
        best_across = across_abs;
        best_along = T(ux) * px + T(uy) * py;
      }
    }
  }
  out[0] = T(range) - best_along;
  out[1] = best_across;
}

/// Return q's residuals (CircleRayResidual or BoxRayResidual) against a leg section centred at
/// `c`: round of `radius`, or a half_x x half_y box with its x axis at (cos_a, sin_a).
template <typename T>
void ReturnRayResidual(const T* c, const ScanPoint& q, bool round, double radius, const T& cos_a,
                       const T& sin_a, double half_x, double half_y, T* out) {
  const double ux = q.p.x() / q.range, uy = q.p.y() / q.range;  // beam direction
  if (round) {
    CircleRayResidual(c, ux, uy, q.range, radius, out);
  } else {
    BoxRayResidual(c, ux, uy, q.range, cos_a, sin_a, half_x, half_y, out);
  }
}

/// sqrt of the Huber weight min(1, k / |r|): scales a residual for the next round of the fits'
/// iteratively reweighted least squares.
inline double HuberSqrtWeight(double abs_residual, double k) {
  return abs_residual <= k ? 1.0 : std::sqrt(k / abs_residual);
}

}  // namespace shelfdock::perception
