#pragma once

#include <cstddef>
#include <vector>

#include "perception/preprocess.hpp"

namespace shelfdock::perception {

/// True when the points [begin, end) continue the surface of their two beam neighbours: both
/// neighbours (points begin - 1 and end) exist, on the next beams but for at most one without a
/// return, each within max_step_m of the piece's end next to it (one surface sampled densely
/// enough), at least min_chord_m apart (a surface wider than a leg, not fragments of one leg),
/// and every point lies between them within tolerance_m of the line through them. A wall seen at
/// a grazing angle returns points farther apart than the break distance, each its own leg-sized
/// cluster; a leg is a discontinuity in the scan, nearer than what surrounds it (or alone), so a
/// piece that merely continues a surface is no leg.
bool ContinuesSurface(const std::vector<ScanPoint>& points, std::size_t begin, std::size_t end,
                      double max_step_m, double min_chord_m, double tolerance_m);

}  // namespace shelfdock::perception
