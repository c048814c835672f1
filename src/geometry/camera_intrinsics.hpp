#pragma once

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

}  // namespace shelfdock::geometry
