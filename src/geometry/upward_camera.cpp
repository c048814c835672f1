#include "geometry/upward_camera.hpp"

namespace shelfdock::geometry {

std::optional<ConfigViolation> FindConfigViolation(const UpwardCamera& c) {
  ConfigChecker check;
  check.Nested("intrinsics", FindConfigViolation(c.intrinsics));
  // config/camera.yaml groups the code's two fields in their own map.
  check.Check(c.code_size_m > 0.0, "code.code_size_m", "> 0 (outer black border side, metres)");
  check.Check(c.code_height_m > 0.0, "code.code_height_m", "> 0 (code above the lens, metres)");
  return check.Result();
}

}  // namespace shelfdock::geometry
