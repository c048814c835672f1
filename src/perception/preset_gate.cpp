#include "perception/preset_gate.hpp"

#include "geometry/angle.hpp"

namespace shelfdock::perception {

bool WithinPreset(const geometry::Pose2& T, const geometry::Pose2& preset, double max_offset_m,
                  double max_yaw_rad, double period_rad) {
  if (max_offset_m > 0.0 && (T.translation() - preset.translation()).norm() > max_offset_m) {
    return false;
  }
  return max_yaw_rad <= 0.0 ||
         geometry::AngleDiffModulo(T.yaw, preset.yaw, period_rad) <= max_yaw_rad;
}

}  // namespace shelfdock::perception
