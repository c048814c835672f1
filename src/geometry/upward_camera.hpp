#pragma once

#include <optional>

#include "geometry/camera_intrinsics.hpp"
#include "geometry/config_violation.hpp"

namespace shelfdock::geometry {

/// The upward camera at the robot's centre and the square code under the shelf (paper 3.5).
/// Rendering (sim) and detection (perception) must agree on these numbers, so they live once.
///
/// Frames. `camera` is a planar frame at the robot's base origin with the base's axes (x
/// forward, y left); `tag` is a planar frame at the code's centre, x along the shelf's long
/// side. T_camera_tag = identity means the code is centred above the camera and aligned with
/// the robot. The optical frame (x_c right, y_c down in the image, z_c up) is tied to `camera`
/// by x_c = y_camera, y_c = -x_camera: the robot's forward direction is the image's top.
struct UpwardCamera {
  CameraIntrinsics intrinsics;
  double code_size_m = 0.08;    ///< [m] side of the code's outer black border
  double code_height_m = 0.30;  ///< [m] height of the code (shelf underside) above the lens
};

/// The first impossible value of the camera and code, keys as in config/camera.yaml: the
/// intrinsics' under `intrinsics`, the code's size and height under `code`.
std::optional<ConfigViolation> FindConfigViolation(const UpwardCamera& camera);

}  // namespace shelfdock::geometry
