#pragma once

#include <vector>

#include "perception/preprocess.hpp"

namespace shelfdock::perception {

/// What the scan says about its own range noise.
struct RangeNoiseEstimate {
  double sigma_m = 0.0;  ///< [m] robust std of one range reading; 0 when too few samples
  int samples = 0;       ///< beam triplets it was taken from
};

/// Estimates the range noise from the scan itself: along a smooth surface the second difference
/// of ranges of three consecutive beams, r[i-1] - 2 r[i] + r[i+1], is nearly zero apart from
/// the noise (its std is sqrt(6) sigma; a surface's own curvature adds r * alpha^2 terms, far
/// below a millimetre at a fraction of a degree). Only triplets of consecutive beams inside one
/// cluster count, and the median absolute value (scaled by 1.4826 for a Gaussian) ignores the
/// corners and edges where the surface turns. Fewer than `min_samples` triplets: sigma_m = 0.
RangeNoiseEstimate EstimateRangeNoise(const std::vector<ScanPoint>& points,
                                      const std::vector<ClusterSpan>& spans, int min_samples = 30);

}  // namespace shelfdock::perception
