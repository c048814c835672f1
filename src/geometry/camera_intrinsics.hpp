#pragma once

#include <optional>

#include "geometry/config_violation.hpp"

namespace shelfdock::geometry {

/// Pinhole intrinsics of a camera without lens distortion (the simulator renders none and the
/// marker detector assumes rectified images). Pixel centres sit at integer coordinates, so the
/// principal point of an ideal 640 x 480 sensor is (319.5, 239.5).
struct CameraIntrinsics {
  int width_px = 640;    ///< [px]
  int height_px = 480;   ///< [px]
  double fx_px = 500.0;  ///< [px] focal length along image columns
  double fy_px = 500.0;  ///< [px] focal length along image rows
  double cx_px = 319.5;  ///< [px] principal point, column
  double cy_px = 239.5;  ///< [px] principal point, row
};

/// The first impossible value of the intrinsics (keys as under `intrinsics` in
/// config/camera.yaml: `fx_px`, ...): sizes up to 32768 px, positive focal lengths, the
/// principal point inside the image.
std::optional<ConfigViolation> FindConfigViolation(const CameraIntrinsics& intrinsics);

}  // namespace shelfdock::geometry
