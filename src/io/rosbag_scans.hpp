#pragma once

#include <functional>
#include <string>
#include <vector>

#include "geometry/laser_scan.hpp"

namespace shelfdock::io {

/// A sensor_msgs/LaserScan topic found in a ROS 1 bag.
struct BagScanTopic {
  std::string topic;
  std::size_t messages = 0;
};

/// Lists the LaserScan topics of a ROS 1 bag (format 2.0). Throws InputError naming the file.
std::vector<BagScanTopic> ListBagScanTopics(const std::string& path);

/// Reads every sensor_msgs/LaserScan on `topic` (all LaserScan topics when empty), in time order.
/// Ranges that the message marks as no return (0, below range_min, at or above range_max, not
/// finite) become NaN, as in the JSON scan format. Throws InputError naming the file and topic.
std::vector<geometry::LaserScan> ReadBagScans(const std::string& path, const std::string& topic);

/// Calls `on_scan` with each LaserScan on `topic` (all when empty) in time order, one scan in
/// memory at a time whatever the bag's length; returns how many there were (0 is not an error
/// here). A message over kMaxBagMessageBytes (input_limits.hpp) is rejected before it is read.
std::size_t ForEachBagScan(const std::string& path, const std::string& topic,
                           const std::function<void(const geometry::LaserScan&)>& on_scan);

}  // namespace shelfdock::io
