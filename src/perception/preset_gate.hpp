#pragma once
// Whether a shelf stands where the map's preset says: the preset gate (PresetGateConfig).

#include "geometry/pose2.hpp"

namespace shelfdock::perception {

/// True when a shelf at `T` stands within `max_offset_m` of `preset` and is turned at most
/// `max_yaw_rad` against it, the heading compared modulo `period_rad` (pi for a rectangular
/// shelf, pi/2 for a square one: the detector cannot tell its ends apart). A bound of 0 is off.
bool WithinPreset(const geometry::Pose2& T, const geometry::Pose2& preset, double max_offset_m,
                  double max_yaw_rad, double period_rad);

}  // namespace shelfdock::perception
