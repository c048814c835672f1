#include "sim/marker_camera.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sim/marker_pattern.hpp"

namespace shelfdock::sim {
namespace {

/// Pixel box [u0, u1) x [v0, v1) that contains the code's quiet zone, clipped to the image.
struct Box {
  int u0, v0, u1, v1;
  bool empty() const { return u0 >= u1 || v0 >= v1; }
  bool contains(int u, int v) const { return u >= u0 && u < u1 && v >= v0 && v < v1; }
};

/// Scene radiance in grey levels (before noise and quantisation) over a box of the image;
/// outside the box the scene is uniform background and needs no storage.
struct Patch {
  Box box;
  std::vector<float> value;

  explicit Patch(const Box& b)
      : box(b), value(b.empty() ? 0 : static_cast<std::size_t>((b.u1 - b.u0) * (b.v1 - b.v0))) {}
  float& at(int u, int v) {
    return value[static_cast<std::size_t>((v - box.v0) * (box.u1 - box.u0) + (u - box.u0))];
  }
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

/// Separable Gaussian blur of the patch. The patch's margin is wider than the kernel, so its
/// rim is background and clamping reads at the rim see what lies beyond it.
void Blur(Patch& patch, double sigma_px) {
  const int radius = static_cast<int>(std::ceil(3.0 * sigma_px));
  std::vector<float> kernel(static_cast<std::size_t>(2 * radius + 1));
  float sum = 0.0f;
  for (int i = -radius; i <= radius; ++i) {
    const float w = static_cast<float>(std::exp(-0.5 * i * i / (sigma_px * sigma_px)));
    kernel[static_cast<std::size_t>(i + radius)] = w;
    sum += w;
  }
  for (float& w : kernel) w /= sum;

  const Box& b = patch.box;
  Patch tmp(b);
  for (int v = b.v0; v < b.v1; ++v) {
    for (int u = b.u0; u < b.u1; ++u) {
      float acc = 0.0f;
      for (int i = -radius; i <= radius; ++i) {
        acc += kernel[static_cast<std::size_t>(i + radius)] *
               patch.at(std::clamp(u + i, b.u0, b.u1 - 1), v);
      }
      tmp.at(u, v) = acc;
    }
  }
  for (int v = b.v0; v < b.v1; ++v) {
    for (int u = b.u0; u < b.u1; ++u) {
      float acc = 0.0f;
      for (int i = -radius; i <= radius; ++i) {
        acc += kernel[static_cast<std::size_t>(i + radius)] *
               tmp.at(u, std::clamp(v + i, b.v0, b.v1 - 1));
      }
      patch.at(u, v) = acc;
    }
  }
}

/// SplitMix64 step: a fast, well-mixed 64-bit stream for per-pixel noise.
uint64_t SplitMix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

/// 65536 standard normal samples, drawn once and normalised to zero mean and unit variance.
/// Sensor noise is then a table lookup per pixel: a 640 x 480 image needs 307k draws, which
/// std::normal_distribution makes the bulk of a render's time.
const std::vector<float>& UnitNormalTable() {
  static const std::vector<float> table = [] {
    std::vector<double> draws(1 << 16);
    std::mt19937_64 rng(0x5EED);
    std::normal_distribution<double> normal(0.0, 1.0);
    double mean = 0.0;
    for (double& d : draws) mean += (d = normal(rng));
    mean /= static_cast<double>(draws.size());
    double var = 0.0;
    for (const double d : draws) var += (d - mean) * (d - mean);
    const double scale = 1.0 / std::sqrt(var / static_cast<double>(draws.size()));
    std::vector<float> out(draws.size());
    for (std::size_t i = 0; i < draws.size(); ++i) {
      out[i] = static_cast<float>((draws[i] - mean) * scale);
    }
    return out;
  }();
  return table;
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
  // Pixel-area integration by supersampling, only where the label can be.
  const int blur_radius = static_cast<int>(std::ceil(3.0 * config.blur_sigma_px));
  const Box box = QuietZoneBox(cam, T_camera_tag, half_total_m, blur_radius + 1);
  Patch radiance(box);
  // Image point (u, v) -> code plane in the camera frame -> code frame -> printed cell
  // (col, row); the chain is affine, so it is evaluated once and stepped per sample.
  const geometry::Pose2 T_tag_camera = T_camera_tag.inverse();
  auto to_cell = [&](double u, double v) -> Eigen::Vector2d {
    const Eigen::Vector2d p_camera(-(v - k.cy_px) / k.fy_px * cam.code_height_m,
                                   (u - k.cx_px) / k.fx_px * cam.code_height_m);
    const Eigen::Vector2d p_tag = T_tag_camera * p_camera;
    // Printed axes of the code: right = +y of the tag frame, down = -x.
    return {(p_tag.y() + half_total_m) / cell_m, (-p_tag.x() + half_total_m) / cell_m};
  };
  const Eigen::Vector2d cell_origin = to_cell(0.0, 0.0);
  const Eigen::Vector2d cell_per_u = to_cell(1.0, 0.0) - cell_origin;
  const Eigen::Vector2d cell_per_v = to_cell(0.0, 1.0) - cell_origin;

  auto level_of = [&](const Eigen::Vector2d& cell) -> double {
    const int col = static_cast<int>(std::floor(cell.x()));
    const int row = static_cast<int>(std::floor(cell.y()));
    if (col < 0 || row < 0 || col >= pattern.total_cells || row >= pattern.total_cells) {
      return background;
    }
    return pattern.IsWhite(col, row) ? white : black;
  };
  auto same_cell = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::floor(a.x()) == std::floor(b.x()) && std::floor(a.y()) == std::floor(b.y());
  };

  const int s = std::max(1, config.supersample);
  const double inv_samples = 1.0 / (s * s);
  for (int v = box.v0; v < box.v1; ++v) {
    for (int u = box.u0; u < box.u1; ++u) {
      // Pixel (u, v) covers [u - 0.5, u + 0.5) x [v - 0.5, v + 0.5). Cells are convex, so a
      // pixel whose four corners share a cell is uniform: only edge pixels are supersampled.
      const Eigen::Vector2d corner = cell_origin + (u - 0.5) * cell_per_u + (v - 0.5) * cell_per_v;
      if (same_cell(corner, corner + cell_per_u) && same_cell(corner, corner + cell_per_v) &&
          same_cell(corner, corner + cell_per_u + cell_per_v)) {
        radiance.at(u, v) = static_cast<float>(level_of(corner + 0.5 * (cell_per_u + cell_per_v)));
        continue;
      }
      double sum = 0.0;
      for (int j = 0; j < s; ++j) {
        for (int i = 0; i < s; ++i) {
          sum += level_of(corner + (i + 0.5) / s * cell_per_u + (j + 0.5) / s * cell_per_v);
        }
      }
      radiance.at(u, v) = static_cast<float>(sum * inv_samples);
    }
  }

  if (config.blur_sigma_px > 0.0 && !box.empty()) Blur(radiance, config.blur_sigma_px);

  geometry::GrayImage image(k.width_px, k.height_px);
  const std::vector<float>& unit_normal = UnitNormalTable();
  uint64_t state = seed;
  uint64_t bits = 0;
  const auto noise_std = static_cast<float>(config.noise_std);
  for (int v = 0; v < image.height; ++v) {
    for (int u = 0; u < image.width; ++u) {
      float level = box.contains(u, v) ? radiance.at(u, v) : background;
      if (noise_std > 0.0f) {
        if ((u & 3) == 0) bits = SplitMix64(state);  // four 16-bit table indices per draw
        level += noise_std * unit_normal[bits & 0xFFFF];
        bits >>= 16;
      }
      image.at(u, v) = static_cast<uint8_t>(std::clamp(level + 0.5f, 0.0f, 255.0f));
    }
  }
  return image;
}

geometry::Pose2 TagInCamera(const geometry::Pose2& T_world_base,
                            const geometry::Pose2& T_world_shelf,
                            const geometry::Pose2& T_base_camera) {
  // The code is printed at the shelf's centre along its long side: T_shelf_tag = identity.
  return (T_world_base * T_base_camera).inverse() * T_world_shelf;
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const CameraConfig& c) {
  geometry::ConfigChecker k;
  k.Nested("", FindConfigViolation(c.camera));  // its keys name their own maps
  k.Check(c.supersample >= 1 && c.supersample <= 16, "render.supersample", "in 1..16");
  k.Check(c.blur_sigma_px >= 0.0 && c.blur_sigma_px <= 20.0, "render.blur_sigma_px",
          "in 0..20 pixels");
  k.Check(c.noise_std >= 0.0, "render.noise_std", ">= 0 grey levels");
  k.Check(c.exposure > 0.0, "render.exposure", "> 0");
  auto grey = [](double level) { return level >= 0.0 && level <= 255.0; };
  k.Check(grey(c.white_level), "render.white_level", "in 0..255 grey levels");
  k.Check(grey(c.black_level), "render.black_level", "in 0..255 grey levels");
  k.Check(grey(c.background_level), "render.background_level", "in 0..255 grey levels");
  k.Check(c.white_level > c.black_level, "render.white_level", "> black_level");
  return k.Result();
}

}  // namespace shelfdock::sim
