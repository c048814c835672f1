#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "perception/preprocess.hpp"

namespace shelfdock::perception {

/// The strongest depth step inside a cluster: the index k in (span.begin, span.end) where
/// |range[k] - range[k-1]| is largest among consecutive points, if that step is at least
/// `min_step_m`. A shelf leg with a person's leg or a box touching it forms one cluster (the gap
/// between them is below the break distance), but the two surfaces rarely stand at the same
/// depth: splitting there gives the leg back. nullopt: no step that large (one smooth surface).
std::optional<std::size_t> StrongestDepthStep(const std::vector<ScanPoint>& points,
                                              const ClusterSpan& span, double min_step_m);

/// Where a leg-sized piece at either end of a wider cluster stands in front of the rest: a leg
/// closer to a wall or a large box behind it than the break distance ends that object's
/// cluster. `front_end`: k such that [span.begin, k) is the piece, `back_begin`: k such that
/// [k, span.end) is; each piece has at least two points, an extent of at most max_extent_m, and
/// the object's first point beyond it lies at least min_step_m farther than the piece's last
/// (the largest such step at each end).
struct EndPieces {
  std::optional<std::size_t> front_end;   ///< end of the piece at the span's start
  std::optional<std::size_t> back_begin;  ///< start of the piece at the span's end
};
/// The end pieces of `span` (see EndPieces).
EndPieces FrontEndPieces(const std::vector<ScanPoint>& points, const ClusterSpan& span,
                         double max_extent_m, double min_step_m);

}  // namespace shelfdock::perception
