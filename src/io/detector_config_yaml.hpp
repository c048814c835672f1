#pragma once

#include <string>

#include "perception/detector_config.hpp"

namespace shelfdock::io {

/// Reads detector parameters from YAML (sections preprocess, leg_search, model_match, leg_fit,
/// shelf_fit; every key optional, defaults from perception::DetectorConfig). An unknown key or
/// an impossible value throws InputError naming the file and the key, e.g.
/// `preprocess.cluster_gap_m`.
perception::DetectorConfig ReadDetectorConfig(const std::string& path);

}  // namespace shelfdock::io
