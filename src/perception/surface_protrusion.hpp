#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "perception/preprocess.hpp"

namespace shelfdock::perception {

/// A piece [begin, end) of a cluster's points.
struct PieceRange {
  std::size_t begin = 0;
  std::size_t end = 0;
};

/// What makes a piece of a wider cluster a protrusion from its surface.
struct ProtrusionLimits {
  double max_extent_m = 0.1;    ///< [m] widest piece (MaxLegExtent)
  double min_step_m = 0.03;     ///< [m] depth step toward the sensor at one of its ends, at least
  double min_offset_m = 0.03;   ///< [m] mean offset in front of the surface, at least
  double offset_sigmas = 4.0;   ///< [-] and at least this many times the noise of that mean
  double range_noise_m = 0.01;  ///< [m] the scan's range noise
  int surface_points = 4;       ///< [-] points on each side the surface's line is fitted to
  double surface_rms_m = 0.03;  ///< [m] those points lie within this RMS of their line
  int max_missing_beams = 3;    ///< [-] beams without a return between two points of a surface
                                ///< (PreprocessConfig::cluster_max_missing_beams)
  /// [m] points beside a piece farther than this from the one before them end its side (a
  /// nearer object, an occluder, standing in front of the surface there); infinite: beam
  /// neighbours only
  double surface_max_step_m = std::numeric_limits<double>::infinity();
  /// [-] fewest points the shorter side may have (an occluder may cut one side short; the
  /// other then needs 3); 3: both sides need 3
  int short_side_points = 3;
  /// A piece at the end of its object, the return past it a step behind (the background seen
  /// past a silhouette edge) or none, may be measured against the surface on its other side
  /// alone (a leg with a person's leg, a box touching it on one side); false: both sides need
  /// short_side_points
  bool open_end = false;
  /// Only pieces near here are looked for (the ROI around a preset): steps farther than
  /// roi_radius_m + max_extent_m from it start none. Empty: anywhere.
  std::optional<Eigen::Vector2d> roi_centre;
  double roi_radius_m = 0.0;  ///< [m]
};

/// Leg-sized pieces inside a cluster that stand out in front of its surface: a leg a few
/// centimetres in front of a wall (a shelf pushed against it, a row's back legs before a rack)
/// is closer to the wall than the break distance, so it lies inside the wall's cluster away from
/// its ends, and with range noise comparable to the gap a step at one of its edges may be lost in
/// the noise. A piece has at least two points, an extent of at most max_extent_m and a depth step
/// of at least min_step_m toward the sensor at its start or away from it at its end (to a beam
/// neighbour, which may lie beyond the cluster); the surface_points on either side of it (at
/// least two each, consecutive beam neighbours, inside the cluster or beyond it: the far point of
/// a leg's edge step is often dropped as a mixed point, which breaks the cluster there) lie on
/// one line within surface_rms_m, and the piece's returns stand in front of that line, along
/// their beams, by a mean of at least min_offset_m and offset_sigmas times the noise of that
/// mean. Of overlapping pieces the one that stands out most (in sigmas) is kept.
std::vector<PieceRange> SurfaceProtrusions(const std::vector<ScanPoint>& points,
                                           const ClusterSpan& span, const ProtrusionLimits& limits);

/// How far the points [begin, end) of `points` stand in front of the surface beside them, in
/// sigmas of their mean offset along their beams (the test SurfaceProtrusions puts each piece
/// to, without the depth step at its ends); nullopt when the points beside them do not make one
/// surface, when either side stands out with them or when they stand less than min_offset_m in
/// front of it. `roi_centre` and `max_extent_m` are not looked at.
std::optional<double> ProtrusionSigmas(const std::vector<ScanPoint>& points, std::size_t begin,
                                       std::size_t end, const ProtrusionLimits& limits);

}  // namespace shelfdock::perception
