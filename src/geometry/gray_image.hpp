#pragma once

#include <cstdint>
#include <vector>

namespace shelfdock::geometry {

/// An 8-bit grey image, row-major without padding: pixel (u, v) is pixels[v * width + u].
/// Shared by the simulator's camera (rendering) and perception (marker detection) so that a
/// synthetic image and a real one go through the same code.
struct GrayImage {
  int width = 0;                ///< [px]
  int height = 0;               ///< [px]
  std::vector<uint8_t> pixels;  ///< width * height grey levels, 0 = black

  GrayImage() = default;
  GrayImage(int width_px, int height_px, uint8_t fill = 0)
      : width(width_px),
        height(height_px),
        pixels(static_cast<std::size_t>(width_px) * static_cast<std::size_t>(height_px), fill) {}

  bool empty() const { return width <= 0 || height <= 0; }
  uint8_t at(int u, int v) const { return pixels[Index(u, v)]; }
  uint8_t& at(int u, int v) { return pixels[Index(u, v)]; }

 private:
  std::size_t Index(int u, int v) const {
    return static_cast<std::size_t>(v) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(u);
  }
};

}  // namespace shelfdock::geometry
