#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geometry/config_violation.hpp"
#include "geometry/gray_image.hpp"
#include "geometry/pose2.hpp"
#include "geometry/upward_camera.hpp"

namespace shelfdock::perception {

/// Settings of the AprilTag 36h11 detector that reads the code under the shelf (paper 3.5).
struct MarkerDetectorConfig {
  double quad_decimate = 2.0;         ///< [-] quads sought at 1/2 resolution; refine_edges restores
                                      ///< full-resolution corners (as accurate as 1, 4x faster)
  double quad_sigma_px = 0.0;         ///< [px] Gaussian blur before quad search, 0 = off
  bool refine_edges = true;           ///< snap quad edges to strong gradients
  double decode_sharpening = 0.25;    ///< [-] sharpening of the decoded bits
  int max_hamming = 1;                ///< [bits] corrected bit errors accepted (0..2)
  double min_decision_margin = 20.0;  ///< [-] weaker decodings are dropped
  double max_height_error_m = 0.05;   ///< [m] reject when the code's estimated height differs
};

/// The first impossible value of the detector settings (keys as under `detector` in
/// config/camera.yaml): decimation >= 1, at most 2 corrected bits, no negative blur or margin.
std::optional<geometry::ConfigViolation> FindConfigViolation(const MarkerDetectorConfig& config);

/// One code seen by the upward camera.
struct MarkerObservation {
  int id = -1;                   ///< the code's id (= the shelf's id)
  geometry::Pose2 T_camera_tag;  ///< [m, m, rad] the code's offset and yaw from the camera
  double height_m = 0.0;         ///< [m] estimated distance from lens to code along the axis
  double decision_margin = 0.0;  ///< [-] AprilTag's decoding confidence, higher is better
  int hamming = 0;               ///< [bits] corrected bit errors
};

/// Detects AprilTag 36h11 codes in a grey image and estimates each one's planar pose from its
/// four corners, the code's known size and the intrinsics (AprilTag's homography followed by
/// orthogonal iteration). Not thread-safe: use one detector per thread.
class MarkerDetector {
 public:
  explicit MarkerDetector(const MarkerDetectorConfig& config = {});
  ~MarkerDetector();
  MarkerDetector(MarkerDetector&&) noexcept;
  MarkerDetector& operator=(MarkerDetector&&) noexcept;
  MarkerDetector(const MarkerDetector&) = delete;
  MarkerDetector& operator=(const MarkerDetector&) = delete;

  /// The best code in the image (highest decision margin), or nullopt when none passes.
  std::optional<MarkerObservation> Detect(const geometry::GrayImage& image,
                                          const geometry::UpwardCamera& camera);

  /// Every code that passes, best first.
  std::vector<MarkerObservation> DetectAll(const geometry::GrayImage& image,
                                           const geometry::UpwardCamera& camera);

 private:
  struct Impl;
  MarkerDetectorConfig config_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shelfdock::perception
