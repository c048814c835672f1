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

}  // namespace shelfdock::perception
