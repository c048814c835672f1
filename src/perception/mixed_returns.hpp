#pragma once
// Returns at a leg's outline that may be blends of the leg and the surface behind it (mixed
// pixels), and how much the leg fits trust their ranges.

#include <cstddef>
#include <vector>

#include "perception/scan_point.hpp"
#include "perception/silhouette_edges.hpp"

namespace shelfdock::perception {

/// The outer returns of a leg that may be blends: the gap [m] from each to the surface its next
/// beam out returned from, 0 where the outer return is no blend. An outer return may be a blend
/// when that beam returned from farther away (the beam's footprint may have straddled the leg's
/// edge and that surface) and the return itself lies more than `min_step_m` behind its inner
/// neighbour (a blend lies between the leg and the surface; on the leg's own face the outer
/// return is no farther than the face allows). A leg of one return is left alone: nothing tells
/// a blend from the leg there.
struct MixedEdges {
  double first_gap_m = 0.0;  ///< [m] the first return's (beam order)
  double last_gap_m = 0.0;   ///< [m] the last return's
  /// The gap of return i of n (0 for an inner return).
  double Gap(std::size_t i, std::size_t n) const {
    if (i == 0) return first_gap_m;
    return i + 1 == n ? last_gap_m : 0.0;
  }
};
/// The MixedEdges of a leg's returns (beam order) and outline.
MixedEdges FindMixedEdges(const std::vector<ScanPoint>& points, const SilhouetteEdges& edges,
                          double min_step_m);

/// The square root of the weight a return's range residual keeps in an iteratively reweighted
/// fit, where that return may be a blend (`gap_m` > 0, MixedEdges): the posterior that it is
/// a plain return of the leg, with the range noise `sigma_m`, against a blend anywhere between
/// the leg and the surface `gap_m` behind the return (blurred by the same noise), a blend having
/// the prior `share`. Near 1 in front of the leg's surface, falling behind it once the noise no
/// longer explains the residual; 1 where the return cannot be a blend (`gap_m` 0, `share` 0).
double MixedReturnSqrtWeight(double range_residual_m, double sigma_m, double gap_m, double share);

}  // namespace shelfdock::perception
