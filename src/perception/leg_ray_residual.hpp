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

// A beam's spot: a beam that misses the section by less than its spot's half-width `spot_m`
// across the beam (at the section's range) still returns from it (a blooming scanner draws thin
// legs wider, WidthBloom), from the part of the section its spot reaches, and its range is that
// part's. Where the spot reaches no part (or spot_m is 0), the range residual is taken at the
// section's point nearest the beam, as before.

/// Round leg: b = u.c along the beam, e = u x c across it; hit at t = b - sqrt(r^2 - e^2). A miss:
/// the range residual at the tangent point (b), or, within the spot, at the nearest point of the
/// circle it reaches (across offset |e| - spot_m), the miss distance |e| - r either way.
template <typename T>
void CircleRayResidual(const T* c, double ux, double uy, double range, double radius, T* out,
                       double spot_m = 0.0) {
  const T b = T(ux) * c[0] + T(uy) * c[1];
  const T e = T(ux) * c[1] - T(uy) * c[0];
  const T e_abs = e < T(0) ? -e : e;
  // How far in front of the centre the circle lies at `offset` across the beam; the floor keeps
  // the derivative finite at the tangent.
  auto depth = [radius](const T& offset) {
    const T h2 = T(radius * radius) - offset * offset;
    return ceres::sqrt(h2 > T(1e-8) ? h2 : T(1e-8));
  };
  if (e_abs < T(radius)) {
    out[0] = T(range) - (b - depth(e));
    out[1] = T(0);
    return;
  }
  out[0] = T(range) - b;
  out[1] = e_abs - T(radius);
  if (spot_m > 0.0) {
    const T reached = e_abs - T(spot_m);
    if (reached < T(radius)) out[0] = T(range) - (b - depth(reached > T(0) ? reached : T(0)));
  }
}

/// Rectangular leg: slab test in the leg's axes (x along G_h). A beam that misses the box is
/// measured against the box's corner nearest to it across the beam (the silhouette corner on
/// its side): the range residual at that corner's distance along the beam, the miss distance
/// across it, as for a round leg; within the spot, the range residual at the nearest corner the
/// spot reaches (across the beam within spot_m, or as near as the silhouette corner). A leg seen
/// nearly face-on has its silhouette corner as often at the back as at the front, 40 mm deeper;
/// its spot meets the front face first. Measured against the back corner, a bloomed return beside
/// a face-on leg pulled the leg and the shelf toward the sensor: on the independent generator the
/// shelf's centre stood 1 mm per metre of range short of the truth along its beam. The slab test's
/// own gap between leaving one slab and entering the other is a distance along the beam: for a beam
/// nearly parallel to a face (a leg seen face-on, beside it a return that a wide beam spot or the
/// noise put just past its edge) it grows as 1 / sin of the grazing angle, a return 12 mm beside a
/// 40 mm leg at 1.6 m then counting a metre off and pulling a shelf fitted to its legs' returns 5
/// cm and 60 mrad away (independent generator, against_wall seed 1 scene 84).
template <typename T>
void BoxRayResidual(const T* c, double ux, double uy, double range, const T& cos_a, const T& sin_a,
                    double half_x, double half_y, T* out, double spot_m = 0.0) {
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
  auto corner = [&](double sx, double sy, T* along, T* across_abs) {
    const T px = c[0] + cos_a * T(sx * half_x) - sin_a * T(sy * half_y);
    const T py = c[1] + sin_a * T(sx * half_x) + cos_a * T(sy * half_y);
    const T across = T(ux) * py - T(uy) * px;
    *across_abs = across < T(0) ? -across : across;
    *along = T(ux) * px + T(uy) * py;
  };
  T best_along(0), best_across(1e9);
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      T along, across_abs;
      corner(sx, sy, &along, &across_abs);
      if (across_abs < best_across) {
        best_across = across_abs;
        best_along = along;
      }
    }
  }
  if (spot_m > 0.0) {
    // The nearest corner the spot reaches: its reach at least to the silhouette corner. The
    // corners are walked again rather than kept from the walk above, which every scan without a
    // bloom takes for every missing beam of every fit.
    const T reach = best_across > T(spot_m) ? best_across : T(spot_m);
    for (const double sx : {-1.0, 1.0}) {
      for (const double sy : {-1.0, 1.0}) {
        T along, across_abs;
        corner(sx, sy, &along, &across_abs);
        if (across_abs <= reach && along < best_along) best_along = along;
      }
    }
  }
  out[0] = T(range) - best_along;
  out[1] = best_across;
}

/// Return q's residuals (CircleRayResidual or BoxRayResidual) against a leg section centred at
/// `c`: round of `radius`, or a half_x x half_y box with its x axis at (cos_a, sin_a); a beam
/// that misses it within its spot's half-width `spot_m` [m] returned from the part it reaches.
template <typename T>
void ReturnRayResidual(const T* c, const ScanPoint& q, bool round, double radius, const T& cos_a,
                       const T& sin_a, double half_x, double half_y, T* out, double spot_m = 0.0) {
  const double ux = q.p.x() / q.range, uy = q.p.y() / q.range;  // beam direction
  if (round) {
    CircleRayResidual(c, ux, uy, q.range, radius, out, spot_m);
  } else {
    BoxRayResidual(c, ux, uy, q.range, cos_a, sin_a, half_x, half_y, out, spot_m);
  }
}

/// sqrt of the Huber weight min(1, k / |r|): scales a residual for the next round of the fits'
/// iteratively reweighted least squares.
inline double HuberSqrtWeight(double abs_residual, double k) {
  return abs_residual <= k ? 1.0 : std::sqrt(k / abs_residual);
}

}  // namespace shelfdock::perception
