#include "sim/marker_camera.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sim/marker_pattern.hpp"

namespace shelfdock::sim {
namespace {

/// A float image of scene radiance in grey levels, before noise and quantisation.
struct Radiance {
  int width;
  int height;
  std::vector<float> value;
  float& at(int u, int v) { return value[static_cast<std::size_t>(v * width + u)]; }
};

/// Pixel box [u0, u1) x [v0, v1) that contains the code's quiet zone, clipped to the image.
struct Box {
  int u0, v0, u1, v1;
  bool empty() const { return u0 >= u1 || v0 >= v1; }
};

/// The planar frames of geometry::UpwardCamera: a point of the code plane at camera-frame
/// (x, y) is seen at optical (x_c, y_c) = (y, -x), and projects to (cx + fx x_c / h,
/// cy + fy y_c / h); the code's own printed axes (right, down) are (y_tag, -x_tag).
Box QuietZoneBox(const geometry::UpwardCamera& cam, const geometry::Pose2& T_camera_tag,
                 double half_total_m, int margin_px) {
  const auto& k = cam.intrinsics;
  double u_min = 1e300, u_max = -1e300, v_min = 1e300, v_max = -1e300;
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      const Eigen::Vector2d p_camera =
          T_camera_tag * Eigen::Vector2d(sx * half_total_m, sy * half_total_m);
      const double u = k.cx_px + k.fx_px * p_camera.y() / cam.code_height_m;
      const double v = k.cy_px - k.fy_px * p_camera.x() / cam.code_height_m;
      u_min = std::min(u_min, u);
      u_max = std::max(u_max, u);
      v_min = std::min(v_min, v);
      v_max = std::max(v_max, v);
    }
  }
  auto clip = [](double value, int hi) {
    return static_cast<int>(std::clamp(value, 0.0, static_cast<double>(hi)));
  };
  return {clip(std::floor(u_min) - margin_px, k.width_px),
          clip(std::floor(v_min) - margin_px, k.height_px),
          clip(std::ceil(u_max) + 1 + margin_px, k.width_px),
          clip(std::ceil(v_max) + 1 + margin_px, k.height_px)};
}

/// Separable Gaussian blur restricted to `box` (outside it the scene is uniform background,
/// which blur leaves unchanged); reads outside the image clamp to the edge.
void BlurInBox(Radiance& image, const Box& box, double sigma_px) {
  const int radius = static_cast<int>(std::ceil(3.0 * sigma_px));
  std::vector<float> kernel(static_cast<std::size_t>(2 * radius + 1));
  float sum = 0.0f;
  for (int i = -radius; i <= radius; ++i) {
    const float w = static_cast<float>(std::exp(-0.5 * i * i / (sigma_px * sigma_px)));
    kernel[static_cast<std::size_t>(i + radius)] = w;
    sum += w;
  }
  for (float& w : kernel) w /= sum;

  Radiance tmp = image;
  for (int v = box.v0; v < box.v1; ++v) {
    for (int u = box.u0; u < box.u1; ++u) {
      float acc = 0.0f;
      for (int i = -radius; i <= radius; ++i) {
        acc += kernel[static_cast<std::size_t>(i + radius)] *
               image.at(std::clamp(u + i, 0, image.width - 1), v);
      }
      tmp.at(u, v) = acc;
    }
  }
  for (int v = box.v0; v < box.v1; ++v) {
    for (int u = box.u0; u < box.u1; ++u) {
      float acc = 0.0f;
      for (int i = -radius; i <= radius; ++i) {
        acc += kernel[static_cast<std::size_t>(i + radius)] *
               tmp.at(u, std::clamp(v + i, 0, image.height - 1));
      }
      image.at(u, v) = acc;
    }
  }
}

}  // namespace

geometry::GrayImage RenderMarker(const CameraConfig& config, int tag_id,
                                 const geometry::Pose2& T_camera_tag, uint64_t seed) {
  const geometry::UpwardCamera& cam = config.camera;
  const auto& k = cam.intrinsics;
  const MarkerPattern pattern = MarkerPatternFor(tag_id);
  const double cell_m = cam.code_size_m / pattern.border_cells;
  const double half_total_m = 0.5 * pattern.total_cells * cell_m;

  const auto background = static_cast<float>(config.background_level * config.exposure);
  const double white = config.white_level * config.exposure;
  const double black = config.black_level * config.exposure;
  Radiance radiance{
      k.width_px, k.height_px,
      std::vector<float>(static_cast<std::size_t>(k.width_px * k.height_px), background)};

  // Pixel-area integration by supersampling, only where the label can be.
  const int blur_radius = static_cast<int>(std::ceil(3.0 * config.blur_sigma_px));
  const Box box = QuietZoneBox(cam, T_camera_tag, half_total_m, blur_radius + 1);
  const geometry::Pose2 T_tag_camera = T_camera_tag.inverse();
  const int s = std::max(1, config.supersample);
  const double inv_samples = 1.0 / (s * s);
  for (int v = box.v0; v < box.v1; ++v) {
    for (int u = box.u0; u < box.u1; ++u) {
      double sum = 0.0;
      for (int j = 0; j < s; ++j) {
        for (int i = 0; i < s; ++i) {
          // Sub-pixel sample; pixel (u, v) covers [u - 0.5, u + 0.5) x [v - 0.5, v + 0.5).
          const double us = u - 0.5 + (i + 0.5) / s;
          const double vs = v - 0.5 + (j + 0.5) / s;
          const Eigen::Vector2d p_camera(-(vs - k.cy_px) / k.fy_px * cam.code_height_m,
                                         (us - k.cx_px) / k.fx_px * cam.code_height_m);
          const Eigen::Vector2d p_tag = T_tag_camera * p_camera;
          // Printed axes of the code: right = y_tag, down = -x_tag.
          const int col = static_cast<int>(std::floor((p_tag.y() + half_total_m) / cell_m));
          const int row = static_cast<int>(std::floor((-p_tag.x() + half_total_m) / cell_m));
          if (col < 0 || row < 0 || col >= pattern.total_cells || row >= pattern.total_cells) {
            sum += background;
          } else {
            sum += pattern.IsWhite(col, row) ? white : black;
          }
        }
      }
      radiance.at(u, v) = static_cast<float>(sum * inv_samples);
    }
  }

  if (config.blur_sigma_px > 0.0 && !box.empty()) {
    BlurInBox(radiance, box, config.blur_sigma_px);
  }

  geometry::GrayImage image(k.width_px, k.height_px);
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> noise(0.0f, static_cast<float>(config.noise_std));
  const bool noisy = config.noise_std > 0.0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const float level = radiance.value[i] + (noisy ? noise(rng) : 0.0f);
    image.pixels[i] = static_cast<uint8_t>(std::clamp(std::lround(level), 0L, 255L));
  }
  return image;
}

geometry::Pose2 TagInCamera(const geometry::Pose2& T_world_base,
                            const geometry::Pose2& T_world_shelf,
                            const geometry::Pose2& T_base_camera) {
  // The code is printed at the shelf's centre along its long side: T_shelf_tag = identity.
  return (T_world_base * T_base_camera).inverse() * T_world_shelf;
}

}  // namespace shelfdock::sim
