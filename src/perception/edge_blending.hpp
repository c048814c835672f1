#pragma once

#include <vector>

#include "perception/scan_point.hpp"

namespace shelfdock::perception {

/// What the scan says about how its sensor makes mixed points at large depth steps.
struct EdgeBlendingEstimate {
  int steps = 0;    ///< clean steps: two surfaces on neighbouring beams, nothing between them
  int bridged = 0;  ///< the same with one return between the two surfaces (a mixed point)
  /// [m] the widest depth the scan shows bridged twice or more, the second widest of those (0:
  /// fewer than two). One bridge alone may be an object standing between two surfaces.
  double widest_bridged_twice_m = 0.0;
  double widest_bridged_m = 0.0;  ///< [m] the depth of the widest of those (0: none)
  /// The share of large depth steps the sensor bridges with a mixed point; 0 when none seen.
  double Share() const {
    const int n = steps + bridged;
    return n > 0 ? static_cast<double>(bridged) / n : 0.0;
  }
};

/// Counts, over a scan's valid returns (beam order, before the trailing-point filter), the depth
/// steps of at least `min_gap_m` between two surfaces that each go on for a beam (the next
/// return out within `flat_m` of the step's return) and how many of them have one return in
/// between, more than `flat_m` from either surface. A beam whose footprint straddles an edge
/// sees both surfaces: a pulsed sensor that separates echoes far apart returns one of them, so
/// its large steps are clean; a sensor (or a simulator) that blends every echo of a beam returns
/// a range between the two at nearly every large step, however far apart they are. Where the
/// share is high, a leg's returns before a far background are such blends as often as not, and
/// their ranges pull the leg toward it.
EdgeBlendingEstimate EstimateEdgeBlending(const std::vector<ScanPoint>& points, double min_gap_m,
                                          double flat_m);

}  // namespace shelfdock::perception
