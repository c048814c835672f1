#pragma once

#include <cstdint>
#include <optional>

#include "geometry/config_violation.hpp"
#include "geometry/gray_image.hpp"
#include "geometry/pose2.hpp"
#include "geometry/upward_camera.hpp"

namespace shelfdock::sim {

/// The upward camera that reads the code under the shelf (paper 3.5), and how it degrades the
/// image: pixel integration (supersampling), defocus blur, exposure, sensor noise.
struct CameraConfig {
  geometry::UpwardCamera camera;   ///< intrinsics, code size and height
  int supersample = 4;             ///< [-] samples per pixel side (pixel-area integration)
  double blur_sigma_px = 0.7;      ///< [px] Gaussian defocus blur, 0 = off
  double noise_std = 2.0;          ///< [grey levels] Gaussian sensor noise, 0 = off
  double exposure = 1.0;           ///< [-] gain on the scene's radiance (1 = nominal)
  double white_level = 220.0;      ///< [grey levels] white paper at nominal exposure
  double black_level = 25.0;       ///< [grey levels] black ink at nominal exposure
  double background_level = 90.0;  ///< [grey levels] shelf underside around the label
};

/// The first impossible value of the camera and its rendering, keys as in config/camera.yaml:
/// the camera's (`intrinsics.fx_px`, `code.code_size_m`, ...), then the rendering's own under
/// `render` (grey levels in 0..255, white brighter than black).
std::optional<geometry::ConfigViolation> FindConfigViolation(const CameraConfig& config);

/// Renders the grey image the camera sees of AprilTag 36h11 code `tag_id` at T_camera_tag
/// (frames as in geometry::UpwardCamera). The code and its white quiet zone may leave the
/// image partly or fully: the image then shows what is left. Deterministic for a given seed.
geometry::GrayImage RenderMarker(const CameraConfig& config, int tag_id,
                                 const geometry::Pose2& T_camera_tag, uint64_t seed);

/// Where the code of a shelf appears to the camera: the code sits at the shelf's centre
/// aligned with its long side, the camera at T_base_camera on the robot (identity: the
/// robot's centre, the paper's set-up).
geometry::Pose2 TagInCamera(const geometry::Pose2& T_world_base,
                            const geometry::Pose2& T_world_shelf,
                            const geometry::Pose2& T_base_camera = geometry::Pose2());

}  // namespace shelfdock::sim
