#pragma once
// Writes small ROS 1 bags for the bag reader's tests (built as C++17 beside the reader, behind
// this header of plain types).

#include <string>
#include <vector>

namespace shelfdock::testing {

/// One sensor_msgs/LaserScan message to write.
struct BagLaserScan {
  std::string topic = "/scan";
  double stamp_s = 1.0;
  float angle_min = -0.5F;
  float angle_increment = 0.1F;
  float range_min = 0.05F;
  float range_max = 25.0F;
  std::vector<float> ranges;
  std::vector<float> intensities;
};

/// Writes `scans` (angle_max from the beam count) and, when `string_topic` is not empty, one
/// std_msgs/String on that topic; an empty `scans` gives a bag without LaserScan topics.
void WriteTestBag(const std::string& path, const std::vector<BagLaserScan>& scans,
                  const std::string& string_topic = "");

}  // namespace shelfdock::testing
