#pragma once

#include <vector>

#include "perception/detector_config.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::perception {

/// What the scan says about how much wider than they stand its sensor draws thin objects.
struct WidthBloomEstimate {
  double bloom_rad = 0.0;  ///< [rad] extra width of every thin object; 0 when too few were seen
  int objects = 0;         ///< thin objects clear of their background it was taken from
};

/// Estimates the scan's width bloom. A receiver that reports a beam's first echo above a low
/// threshold returns from a bright thin object as soon as any part of the beam's spot touches
/// it, so every such object looks wider by about the spot's angle (at 4 m a 40 mm leg can look
/// 80-100 mm wide to a scanner with a 15 mrad spot); a receiver that needs a good share of the
/// spot on a surface draws it true within a beam. Which one a scan comes from is read off its
/// thinnest objects: for each cluster of two returns or more (a lone return may be a stray echo)
/// and at most EvidenceConfig::width_bloom_max_extent_m whose first and last returns stand at
/// least width_bloom_min_step_m in front of the next returns out on both sides (a leg or a post
/// clear of what lies behind it), its seen angle (the beams it spans, less half a beam of
/// quantisation) minus the angle `narrowest_leg_m` (the thinnest leg of any model) subtends at
/// its range; the estimate is the width_bloom_quantile of those over the scan, raised by
/// width_bloom_order_share of that order statistic's expected shortfall from beam quantisation,
/// at least 0, at most width_bloom_max_rad (0: off). One thin post or leg drawn true anywhere in
/// the scan pins it near 0, so a sensor that draws objects true keeps the strict width checks;
/// fewer than `min_objects` such objects: 0. `raw_points` are the scan's valid returns in beam
/// order (ScanToPoints), `points` and `spans` the preprocessed ones (PreprocessOutput), whose Eq. 1
/// filter may have dropped the background return beside an object.
WidthBloomEstimate EstimateWidthBloom(const std::vector<ScanPoint>& raw_points,
                                      const std::vector<ScanPoint>& points,
                                      const std::vector<ClusterSpan>& spans,
                                      double angle_increment_rad, double narrowest_leg_m,
                                      const EvidenceConfig& config);

}  // namespace shelfdock::perception
