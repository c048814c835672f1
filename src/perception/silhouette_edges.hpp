#pragma once

#include <optional>
#include <vector>

#include "perception/scan_point.hpp"

namespace shelfdock::perception {

/// Where an object's outline ends across the beams, as far as the scan shows it.
struct SilhouetteEdges {
  /// [rad] Bearing of the edge before the first point (after the last): halfway between that
  /// point's beam and the next beam out, when that beam passed beside the object and returned
  /// from farther away. Empty when the next beam returned nothing (a dropout on a shiny leg seen
  /// at a grazing angle, or nothing within range) or something nearer (an occluder): the object
  /// may go on there, so its outline says nothing on that side.
  std::optional<double> before_rad;
  std::optional<double> after_rad;
  /// An open side where the object may go on well past its outer return: the next beam out
  /// returned from something nearer (an occluder), or there is no next beam (the field of view
  /// ends there). A dropout beside it leaves the side open but not cut: a dark leg at a grazing
  /// angle drops a beam or so.
  bool before_cut = false;
  bool after_cut = false;
  /// Whether the outline is cut on either side (the object may be larger than it looks).
  bool cut() const { return before_cut || after_cut; }
  /// [m] How far behind the outer return the next beam out returned (negative: nearer); empty
  /// where that beam returned nothing or the scan has none.
  std::optional<double> before_step_m;
  std::optional<double> after_step_m;
};

/// The edges of the object whose returns run from `first` to `last` (beam order), read from
/// `scan_points`, the scan's valid returns in beam order before any filtering: a trailing
/// (mixed) point straddles the edge, so it marks the edge as well as the background does. A
/// neighbour counts as beside the object when it is at least min_depth_m farther than the
/// object's point next to it.
SilhouetteEdges FindSilhouetteEdges(const std::vector<ScanPoint>& scan_points,
                                    const ScanPoint& first, const ScanPoint& last,
                                    double min_depth_m);

}  // namespace shelfdock::perception
