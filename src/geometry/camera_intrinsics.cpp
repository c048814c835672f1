#include "geometry/camera_intrinsics.hpp"

namespace shelfdock::geometry {
namespace {

constexpr int kMaxSide_px = 32768;

bool InImage(double coordinate_px, int side_px) {
  return coordinate_px >= 0.0 && coordinate_px <= side_px;
}

}  // namespace

std::optional<ConfigViolation> FindConfigViolation(const CameraIntrinsics& k) {
  ConfigChecker check;
  check.Check(k.width_px > 0 && k.width_px <= kMaxSide_px, "width_px", "in 1..32768 pixels");
  check.Check(k.height_px > 0 && k.height_px <= kMaxSide_px, "height_px", "in 1..32768 pixels");
  check.Check(k.fx_px > 0.0, "fx_px", "> 0 pixels");
  check.Check(k.fy_px > 0.0, "fy_px", "> 0 pixels");
  check.Check(InImage(k.cx_px, k.width_px), "cx_px", "inside the image (0..width)");
  check.Check(InImage(k.cy_px, k.height_px), "cy_px", "inside the image (0..height)");
  return check.Result();
}

}  // namespace shelfdock::geometry
