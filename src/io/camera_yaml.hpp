#pragma once

#include <string>

#include "perception/marker_detector.hpp"
#include "sim/marker_camera.hpp"

namespace shelfdock::io {

/// Everything config/camera.yaml describes: the upward camera and the code it reads (shared by
/// rendering and detection), how the simulator degrades its images, and the detector settings.
struct CameraSetup {
  sim::CameraConfig camera;  ///< camera.camera is the geometry::UpwardCamera both sides use
  perception::MarkerDetectorConfig detector;
};

/// Reads a camera file: maps `intrinsics` (width, height, fx, fy, cx, cy), `code` (size,
/// height), `render` (supersample, blur_sigma, noise_std, exposure, white_level, black_level,
/// background_level) and `detector` (quad_decimate, quad_sigma, refine_edges,
/// decode_sharpening, max_hamming, min_decision_margin, max_height_error). Every key is
/// optional (the structs hold the defaults), units are px, m and grey levels. Throws
/// InputError naming the file and the key.
CameraSetup ReadCameraSetup(const std::string& path);

}  // namespace shelfdock::io
