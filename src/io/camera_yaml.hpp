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

/// Reads a camera file: maps `intrinsics` (geometry::CameraIntrinsics), `code` (the code fields
/// of geometry::UpwardCamera), `render` (sim::CameraConfig) and `detector`
/// (perception::MarkerDetectorConfig), each key named exactly as its struct field (`fx_px`,
/// `code_size_m`, `blur_sigma_px`, ...). Every key is optional (the structs hold the defaults),
/// units are px, m and grey levels. Throws InputError naming the file and the key.
CameraSetup ReadCameraSetup(const std::string& path);

}  // namespace shelfdock::io
