#pragma once
// Documented limits on outside input, checked before the work is done: a file or line beyond
// them is rejected with an io::InputError naming the limit, never read into memory first.

#include <cstddef>

namespace shelfdock::io {

/// Beams in one scan (ranges and intensities). Real 2D LiDARs give 270-3600 beams a turn; the
/// limit leaves room for 0.01 deg heads while keeping one scan's work (clustering, leg search)
/// well under a second.
inline constexpr std::size_t kMaxBeamsPerScan = 65536;

/// Elements of any one JSON array in a scan file (the scans of a JSON array file included).
inline constexpr std::size_t kMaxJsonArrayElements = kMaxBeamsPerScan;

/// Nesting in a scan file's JSON (a scan needs 3: array of scans, scan, ranges).
inline constexpr int kMaxScanJsonDepth = 8;

/// One JSON Lines line: a scan at the beam limit written with 17 significant digits and
/// intensities fits.
inline constexpr std::size_t kMaxScanLineBytes = std::size_t{4} << 20;

/// A scan file read as one JSON document (an object or an array of scans). Longer recordings
/// belong in JSON Lines, which is read one scan at a time whatever its length.
inline constexpr std::size_t kMaxScanDocumentBytes = std::size_t{64} << 20;

/// YAML config files (models, detector, docking, scenario, lidar, robot, camera).
inline constexpr std::size_t kMaxYamlFileBytes = std::size_t{1} << 20;

/// Nesting of YAML flow collections and block indentation levels: yaml-cpp parses recursively,
/// and a deeply nested document would exhaust the stack.
inline constexpr int kMaxYamlDepth = 64;

/// Shelf models in one models file (the paper has 4; a warehouse a few dozen).
inline constexpr std::size_t kMaxShelfModels = 256;

/// Entries of each list of a scenario (shelves, walls, posts, people, ...) and points of one
/// polygon: a simulated scan ray-casts every object, so a scene's size bounds a scan's cost.
inline constexpr std::size_t kMaxSceneObjects = 2000;

/// One chunk of a ROS bag, uncompressed (rosbag writes 768 KB chunks by default).
inline constexpr std::size_t kMaxBagChunkBytes = std::size_t{64} << 20;

/// One ROS bag message (a LaserScan at the beam limit with intensities is ~520 KB).
inline constexpr std::size_t kMaxBagMessageBytes = std::size_t{1} << 20;

}  // namespace shelfdock::io
